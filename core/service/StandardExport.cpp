#include "service/StandardExport.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(StandardExport)
};

QString number(double v, int precision)
{
    return QString::number(v, 'g', precision);
}

} // namespace

ParameterOrigin parameterOrigin(const std::vector<double> &determined, int i)
{
    if (i < 0 || size_t(i) >= determined.size() || !std::isfinite(determined[size_t(i)]))
        return ParameterOrigin::Unknown;
    return determined[size_t(i)] >= 0.5 ? ParameterOrigin::Data : ParameterOrigin::Prior;
}

QString parameterOriginText(ParameterOrigin origin)
{
    switch (origin) {
    case ParameterOrigin::Data:
        return Text::tr("data");
    case ParameterOrigin::Prior:
        // Not "prior": the geometric prior keeps the value near the URDF's, the data still move
        // it (and what they determine in combination with other parameters).
        return Text::tr("undetermined (kept near the prior)");
    case ParameterOrigin::Unknown:
        break;
    }
    return QStringLiteral("?");
}

std::vector<IdentifiedJoint> urdfJointTerms(const ChainModel &model, const Eigen::VectorXd &pi)
{
    const int n = model.dof();
    const JointTerms &t = model.jointTerms();
    if (pi.size() != model.standardCount()) {
        throw Error(Text::tr("%1 standard parameters given, the model has %2")
                        .arg(pi.size())
                        .arg(model.standardCount()));
    }
    std::vector<IdentifiedJoint> terms(static_cast<size_t>(n));
    for (int j = 0; j < n; ++j) {
        // pi: 10 n inertia entries, then per joint its terms in JointTerms' order.
        Eigen::Index at = 10 * n + Eigen::Index(j) * t.count();
        IdentifiedJoint &f = terms[size_t(j)];
        if (t.armature)
            f.armature = pi[at++];
        if (t.viscous)
            f.viscous = pi[at++];
        if (t.coulomb)
            f.coulomb = pi[at++];
        if (t.offset)
            f.offset = pi[at++];
    }
    return terms;
}

QStringList determinedNotes(const ChainModel &model, const Eigen::VectorXd &pi,
                            const std::vector<double> &determined)
{
    if (determined.empty())
        return {};
    const QList<ParameterInfo> info = model.standardParameters();
    QStringList lines = {
        QStringLiteral("What the data determined. Per standard parameter: value, unit, the share"),
        QStringLiteral(
            "of its direction (the parameter alone, scaled by its regressor column) the"),
        QStringLiteral("data see, and \"data\" (at least 0.5: identified) or \"undetermined\""),
        QStringLiteral("(below: kept near the original URDF's value, not at it, or known only in"),
        QStringLiteral("combination with others).")};
    int width = 0;
    for (const ParameterInfo &p : info)
        width = std::max(width, int(p.name.size() + 1 + p.unit.size()));
    const int n = model.dof();
    const int perJoint = std::max(1, model.jointTerms().count());
    QString group;
    for (int i = 0; i < int(info.size()) && i < int(pi.size()); ++i) {
        const ParameterInfo &p = info.at(i);
        const int k = i < 10 * n ? i / 10 : (i - 10 * n) / perJoint;
        const ChainJoint &joint = model.chain().joints[size_t(k)];
        const QString here = i < 10 * n
                                 ? QStringLiteral("link %1 (%2)").arg(k + 1).arg(joint.link)
                                 : QStringLiteral("joint %1 (%2)").arg(k + 1).arg(joint.name);
        if (here != group) {
            group = here;
            lines << QStringLiteral("  %1:").arg(group);
        }
        const ParameterOrigin origin = parameterOrigin(determined, i);
        lines << QStringLiteral("    %1 %2  %3  %4")
                     .arg(number(pi[i], 6).rightJustified(13),
                          (p.name + QLatin1Char(' ') + p.unit).leftJustified(width),
                          std::isfinite(determined[size_t(i)])
                              ? QString::number(determined[size_t(i)], 'f', 2)
                              : QStringLiteral("   -"),
                          origin == ParameterOrigin::Data    ? QStringLiteral("data")
                          : origin == ParameterOrigin::Prior ? QStringLiteral("undetermined")
                                                             : QStringLiteral("unknown"));
    }
    return lines;
}

void setStandardParameters(ParameterFileContent &content, const ChainModel &model,
                           const Eigen::VectorXd &pi, const std::vector<double> &determined)
{
    content.standardParameters = model.standardParameters();
    content.standardValues = pi;
    content.standardDetermined = determined;
}

ParameterFileContent logFileHeader(const ChainModel &model, const QString &robotModel,
                                   const QString &description,
                                   const std::optional<ControllerSettings> &controller)
{
    ParameterFileContent c;
    c.robotModel = robotModel;
    c.robotDescription = description;
    c.hasController = controller.has_value();
    if (controller)
        c.controller = *controller;
    for (int j = 0; j < model.dof(); ++j)
        c.jointNodes.append(j + 1);
    c.created = QDateTime::currentDateTimeUtc();
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.law = QStringLiteral("improved"); // its zero-phase filter F(s) prepares the logs
    c.parameters = model.parameters();
    return c;
}

} // namespace learnid
