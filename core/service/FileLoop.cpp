#include "service/FileLoop.h"

#include "io/AtomicFile.h"
#include "io/ParameterFile.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "session/ScenarioRobot.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(FileLoop)
};

QString native(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

} // namespace

LoopScenario loopScenario(const Scenario &scenario)
{
    LoopScenario s;
    s.model = makeRobotModel(scenario.model, scenario.urdf);
    if (!s.model)
        throw Error(Text::tr("unknown robot model \"%1\"").arg(scenario.model));
    s.scenario = withRobotDefaults(scenario, *s.model);
    return s;
}

QStringList writeLoopFiles(const LoopFiles &files)
{
    for (const QString &folder : files.folders) {
        if (!QDir().mkpath(folder))
            throw Error(Text::tr("cannot create the folder %1").arg(native(folder)));
    }
    writeFilesAtomically(files.files);
    for (const QString &path : files.obsolete)
        QFile::remove(path); // unreferenced from now on: a file left behind does no harm
    QStringList written;
    for (const auto &file : files.files)
        written << file.first;
    return written;
}

std::optional<LoopHistory> readLoopHistory(const QString &dir)
{
    const QString index = QDir(dir).filePath(QLatin1String(loopHistoryIndexName));
    if (!QFileInfo::exists(index))
        return std::nullopt;
    return loopHistoryFromJson(readFile(index), native(index));
}

void checkHistoryFits(const LoopHistory &history, const QString &dir, const LoopScenario &s)
{
    const RobotModel &model = *s.model;
    if (history.robotModel != model.id() || history.joints != model.dof() ||
        history.parameters != model.parameterCount()) {
        throw Error(Text::tr("the history %1 is of robot %2 (%3 joints, %4 parameters), the "
                             "scenario's robot is %5 (%6 joints, %7 parameters)")
                        .arg(native(dir), history.robotModel)
                        .arg(history.joints)
                        .arg(history.parameters)
                        .arg(model.id())
                        .arg(model.dof())
                        .arg(model.parameterCount()));
    }
    const bool payload = s.scenario.payload.enabled;
    if (payload && history.payloadLink.isEmpty())
        throw Error(Text::tr("the history %1 was made by the arm's learning loop (a scenario "
                             "without a payload section); the scenario learns a payload: give "
                             "another --history for the payload's loop")
                        .arg(native(dir)));
    if (!payload && !history.payloadLink.isEmpty())
        throw Error(Text::tr("the history %1 learns the payload on %2 (a scenario with a payload "
                             "section); the scenario learns the arm: give another --history for "
                             "the arm's loop")
                        .arg(native(dir), history.payloadLink));
    // The payload's loop holds the arm fixed: its law learns nothing there.
    if (!payload && history.law != s.scenario.law) {
        throw Error(Text::tr("the history %1 learns with the law %2, the scenario with %3: a "
                             "history keeps its law (start a new history for another)")
                        .arg(native(dir), history.law, s.scenario.law));
    }
}

Eigen::VectorXd readEstimateFile(const QString &path, const RobotModel &model, const QString &what)
{
    const ParameterFileContent c = readParameterFile(path);
    if (c.robotModel != model.id() || c.values.size() != model.parameterCount()) {
        throw Error(Text::tr("%1: %2 holds %3 parameters of robot %4; the scenario's robot %5 has "
                             "%6")
                        .arg(what, native(path))
                        .arg(c.values.size())
                        .arg(c.robotModel, model.id())
                        .arg(model.parameterCount()));
    }
    const QList<ParameterInfo> names = model.parameters();
    for (int i = 0; i < int(names.size()); ++i) {
        if (c.parameters.at(i).name != names.at(i).name)
            throw Error(Text::tr("%1: %2: parameter %3 is \"%4\", the robot's is \"%5\"")
                            .arg(what, native(path))
                            .arg(i + 1)
                            .arg(c.parameters.at(i).name, names.at(i).name));
    }
    return c.values;
}

QString preTrialCheckText(const PreTrialCheck &check, int trialIndex, const QString &estimateSource,
                          const QStringList &identifiability)
{
    QStringList lines;
    lines << (check.passed()
                  ? Text::tr("trial %1: check passed, the trial may run.").arg(trialIndex)
                  : Text::tr("trial %1 refused: %2").arg(trialIndex).arg(check.reason()));
    lines << Text::tr("feedforward built with: %1").arg(estimateSource);
    if (!check.planningError.isEmpty())
        return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
    const SafetyVerdict &v = check.verdict;
    lines << Text::tr("planned motion: %1 s, %2 s with rests, %3 samples of %4 s")
                 .arg(v.motionDuration, 0, 'f', 3)
                 .arg(check.plan.desired.duration(), 0, 'f', 3)
                 .arg(check.plan.samples())
                 .arg(check.plan.desired.samplePeriod);
    if (!v.physical)
        lines << Text::tr("closed loop: estimate not physical (mass matrix not positive definite)");
    else if (v.stable)
        lines << Text::tr("closed loop: stable, max |z| = %1, decay rate %2 1/s")
                     .arg(v.worstSpectralRadius, 0, 'f', 6)
                     .arg(v.worstDecayRate, 0, 'g', 4);
    else
        lines << Text::tr("closed loop: UNSTABLE, max |z| = %1 at t = %2 s (growth %3 1/s)")
                     .arg(v.worstSpectralRadius, 0, 'f', 6)
                     .arg(v.worstTime, 0, 'f', 3)
                     .arg(v.worstDecayRate, 0, 'g', 4);
    lines << Text::tr("joint   peak [N m]  limit [N m]     use");
    for (Eigen::Index j = 0; j < v.peakTorque.size(); ++j) {
        const double limit = j < v.torqueLimit.size() ? v.torqueLimit[j] : 0.0;
        lines << QStringLiteral("%1 %2 %3 %4 %")
                     .arg(j + 1, 5)
                     .arg(v.peakTorque[j], 12, 'f', 3)
                     .arg(limit, 12, 'f', 3)
                     .arg(limit > 0 ? 100.0 * v.peakTorque[j] / limit : 0.0, 7, 'f', 1);
    }
    lines << identifiability;
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace learnid
