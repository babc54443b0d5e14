#include "ui/PayloadText.h"

#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadText)
};

QString millimetres(const Eigen::Vector3d &c)
{
    // Rounded to 0.1 mm first, so that a rounding of zero shows no sign.
    const Eigen::Vector3d mm = (10000.0 * c).array().round() / 10.0 + 0.0;
    return QStringLiteral("(%1, %2, %3)")
        .arg(mm.x(), 0, 'f', 1)
        .arg(mm.y(), 0, 'f', 1)
        .arg(mm.z(), 0, 'f', 1);
}

QString seen(bool identified)
{
    return identified ? Text::tr("seen") : Text::tr("not seen: kept at the prior");
}

} // namespace

QString payloadPreviewHtml(const PayloadPreview &p, const SimulatedPayload &simulated)
{
    QString t = QStringLiteral("<p>") +
                Text::tr("%1; the payload on <b>%2</b>, the arm's model held fixed.")
                    .arg(p.robotDescription.toHtmlEscaped(), p.link.toHtmlEscaped());
    if (simulated.present) {
        t += QLatin1Char(' ') + Text::tr("The simulation carries %1 kg at %2 mm.")
                                    .arg(simulated.mass, 0, 'g', 4)
                                    .arg(millimetres(simulated.com));
    }
    t += QStringLiteral("</p><p>");
    t += p.baselineTrials > 0
             ? Text::tr("%1 baseline trial(s) of the same timed path without the payload, then %2 "
                        "payload trial(s).")
                   .arg(p.baselineTrials)
                   .arg(p.trials)
             : Text::tr("%n payload trial(s), no baseline trial.", nullptr, p.trials);
    t += QStringLiteral("</p><p>");
    const PayloadObservability &o = p.observability;
    t += Text::tr("The path determines <b>%1 of the payload's 10 parameters</b>: mass %2, centre "
                  "of mass %3, inertia %4.")
             .arg(o.rank)
             .arg(seen(o.massIdentified()), seen(o.comIdentified()), seen(o.inertiaIdentified()));
    t += QStringLiteral("</p>");
    if (!p.advice.isEmpty()) {
        t += QStringLiteral("<ul>");
        for (const QString &line : p.advice)
            t += QStringLiteral("<li>") + line.toHtmlEscaped() + QStringLiteral("</li>");
        t += QStringLiteral("</ul>");
    }
    t += QStringLiteral("<p>");
    t += p.checkReason.isEmpty() ? Text::tr("The first trial passes its check.")
                                 : QStringLiteral("<span style=\"color:#b3261e\">") +
                                       Text::tr("The first trial would be refused: %1")
                                           .arg(p.checkReason.toHtmlEscaped()) +
                                       QStringLiteral("</span>");
    return t + QStringLiteral("</p>");
}

QString payloadResultHtml(const PayloadRunResult &r)
{
    const PayloadEstimate &e = r.fit.estimate;
    const PayloadObservability &o = e.observability;
    QString t = QStringLiteral("<p>") +
                Text::tr("The payload after trial %1: %2 of 10 directions determined "
                         "(condition %3); bound: %4.")
                    .arg(r.learnedTrial)
                    .arg(o.rank)
                    .arg(o.condition, 0, 'f', 1)
                    .arg(r.prior.bound.describe().toHtmlEscaped());
    t += QLatin1Char(' ') + Text::tr("Mass <b>%1 kg</b> (standard error %2 kg), centre of mass "
                                     "<b>%3 mm</b>.")
                                .arg(e.body.mass, 0, 'f', 4)
                                .arg(e.bodyStandardError[0], 0, 'g', 2)
                                .arg(millimetres(e.body.com));
    if (!e.comInsideBound) {
        t += QLatin1Char(' ') + QStringLiteral("<span style=\"color:#b3261e\">") +
             Text::tr("Its centre of mass lies outside the bound.") + QStringLiteral("</span>");
    }
    return t + QStringLiteral("</p>");
}

} // namespace learnid
