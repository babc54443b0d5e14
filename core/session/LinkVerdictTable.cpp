#include "session/LinkVerdictTable.h"

#include "model/ChainModel.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(LinkVerdictTable)
};

QString moment(double v)
{
    return std::isfinite(v) ? QString::number(v, 'g', 3) : QStringLiteral("-");
}

QString yesNo(bool yes)
{
    return yes ? Text::tr("yes") : Text::tr("no");
}

} // namespace

LinkVerdictTable linkVerdictTable(const ChainModel &model, const EstimateConsistency &verdict)
{
    LinkVerdictTable t;
    const PlausibilityRule rule;
    t.title = Text::tr("Per link: physically consistent (a real body), and plausible (a body a "
                       "robot's link could be: its smallest principal moment of inertia about the "
                       "centre of mass I1 at least %1 % of the CAD link's, (I1 + I2) / I3 at least "
                       "%2, the centre of mass inside the link's bounding volume).")
                  .arg(QString::number(100.0 * rule.minMomentShare, 'g', 3),
                       QString::number(1.0 + rule.triangleMargin, 'f', 2));
    t.header = QStringList{
        Text::tr("link"),           Text::tr("I1 [kg m^2]"),   Text::tr("CAD I1 [kg m^2]"),
        Text::tr("(I1 + I2) / I3"), Text::tr("CoM in volume"), Text::tr("consistent"),
        Text::tr("plausible")};
    if (!verdict.applicable || verdict.plausibility.size() != verdict.links.size())
        return t;
    for (const LinkPlausibility &p : verdict.plausibility) {
        const bool consistent = verdict.links.at(size_t(p.link)).consistent;
        const bool massive = p.mass > 0.0;
        t.rows << QStringList{
            QStringLiteral("%1 %2").arg(p.link + 1).arg(model.chain().joints[size_t(p.link)].link),
            massive ? moment(p.moments[0]) : QStringLiteral("-"),
            moment(p.cadSmallestMoment),
            massive && std::isfinite(p.triangleRatio) ? QString::number(p.triangleRatio, 'f', 3)
                                                      : QStringLiteral("-"),
            p.hasVolume ? yesNo(p.volumeOk) : QStringLiteral("-"),
            yesNo(consistent),
            yesNo(consistent && p.plausible)};
        t.plausible << (consistent && p.plausible);
    }
    return t;
}

QString linkVerdictText(const LinkVerdictTable &table)
{
    QList<int> widths;
    for (const QString &h : table.header)
        widths << int(h.size());
    for (const QStringList &row : table.rows)
        for (int c = 0; c < row.size() && c < widths.size(); ++c)
            widths[c] = std::max(widths[c], int(row[c].size()));
    const auto line = [&](const QStringList &cells) {
        QStringList out;
        for (int c = 0; c < cells.size() && c < widths.size(); ++c)
            out << (c == 0 ? cells[c].leftJustified(widths[c])
                           : cells[c].rightJustified(widths[c]));
        return out.join(QStringLiteral("  ")) + QLatin1Char('\n');
    };
    QString text = line(table.header);
    for (const QStringList &row : table.rows)
        text += line(row);
    return text;
}

} // namespace learnid
