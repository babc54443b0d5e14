#include "ui/ScenarioFields.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

using Kind = ScenarioField::Kind;

Eigen::VectorXd one(double v)
{
    return Eigen::VectorXd::Constant(1, v);
}

ScenarioField number(QString key, QString label, QString unit,
                     std::function<double &(Scenario &)> ref)
{
    ScenarioField f;
    f.key = std::move(key);
    f.label = std::move(label);
    f.unit = std::move(unit);
    f.read = [ref](const Scenario &s) {
        return one(ref(const_cast<Scenario &>(s)));
    };
    f.write = [ref](Scenario &s, const Eigen::VectorXd &v) {
        ref(s) = v[0];
    };
    return f;
}

ScenarioField vector(QString key, QString label, QString unit,
                     std::function<Eigen::VectorXd &(Scenario &)> ref)
{
    ScenarioField f;
    f.key = std::move(key);
    f.label = std::move(label);
    f.unit = std::move(unit);
    f.kind = Kind::Vector;
    f.expectedCount = 0;
    f.read = [ref](const Scenario &s) {
        return ref(const_cast<Scenario &>(s));
    };
    f.write = [ref](Scenario &s, const Eigen::VectorXd &v) {
        ref(s) = v;
    };
    return f;
}

template <typename T>
ScenarioField integer(QString key, QString label, std::function<T &(Scenario &)> ref)
{
    ScenarioField f;
    f.key = std::move(key);
    f.label = std::move(label);
    f.kind = Kind::Integer;
    f.minimum = std::max(f.minimum, double(std::numeric_limits<T>::min()));
    f.maximum = std::min(f.maximum, double(std::numeric_limits<T>::max()));
    f.read = [ref](const Scenario &s) {
        return one(double(ref(const_cast<Scenario &>(s))));
    };
    f.write = [ref](Scenario &s, const Eigen::VectorXd &v) {
        ref(s) = T(v[0]);
    };
    return f;
}

QString label(const char *text)
{
    return QCoreApplication::translate("learnid::ScenarioFields", text);
}

} // namespace

QList<ScenarioFieldGroup> scenarioFieldGroups()
{
    ScenarioField start;
    start.key = QStringLiteral("path.start");
    start.label = QCoreApplication::translate("learnid::ScenarioFields", "Start (x, y)");
    start.unit = QStringLiteral("m");
    start.kind = Kind::Vector;
    start.expectedCount = 2;
    start.read = [](const Scenario &s) {
        return Eigen::VectorXd(s.line.start);
    };
    start.write = [](Scenario &s, const Eigen::VectorXd &v) {
        s.line.start = v.head<2>();
    };
    start.lineOnly = true;
    ScenarioField length =
        number(QStringLiteral("path.length"),
               QCoreApplication::translate("learnid::ScenarioFields", "Length"),
               QStringLiteral("m"), [](Scenario &s) -> double & { return s.line.length; });
    length.lineOnly = true;
    ScenarioField direction =
        number(QStringLiteral("path.directionDeg"),
               QCoreApplication::translate("learnid::ScenarioFields", "Direction"),
               QStringLiteral("deg"), [](Scenario &s) -> double & { return s.line.directionDeg; });
    direction.lineOnly = true;
    ScenarioField limits = vector(
        QStringLiteral("robot.torqueLimits"),
        QCoreApplication::translate("learnid::ScenarioFields", "Limit per joint"),
        QStringLiteral("N m"), [](Scenario &s) -> Eigen::VectorXd & { return s.torqueLimits; });
    limits.emptyTakesRobot = true;
    ScenarioField initial =
        vector(QStringLiteral("robot.initialParameters"),
               QCoreApplication::translate("learnid::ScenarioFields", "Initial parameters"),
               QString(), [](Scenario &s) -> Eigen::VectorXd & { return s.initialParameters; });
    initial.emptyTakesRobot = true;
    ScenarioField truth =
        vector(QStringLiteral("simulation.trueParameters"),
               label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "True parameters")), QString(),
               [](Scenario &s) -> Eigen::VectorXd & { return s.simulation.trueParameters; });
    truth.emptyTakesRobot = true;

    const ScenarioField trials =
        integer<int>(QStringLiteral("estimator.iterations"),
                     label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Number of trials")),
                     [](Scenario &s) -> int & { return s.iterations; });

    return {
        {label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Path")),
         {start, length, direction,
          number(QStringLiteral("path.restBefore"),
                 label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Rest before the motion")),
                 QStringLiteral("s"), [](Scenario &s) -> double & { return s.restBefore; }),
          number(QStringLiteral("path.restAfter"),
                 label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Rest after the motion")),
                 QStringLiteral("s"), [](Scenario &s) -> double & { return s.restAfter; })}},
        {QCoreApplication::translate("learnid::ScenarioFields", "Torque limits"),
         {limits,
          number(QStringLiteral("path.planningFraction"),
                 QCoreApplication::translate("learnid::ScenarioFields", "Planning fraction"),
                 QString(), [](Scenario &s) -> double & { return s.planningFraction; }),
          integer<int>(QStringLiteral("path.gentleTrials"),
                       label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Gentle first trials")),
                       [](Scenario &s) -> int & { return s.gentleTrials; }),
          number(QStringLiteral("path.gentleSpeed"),
                 label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Gentle trials' speed")),
                 QString(), [](Scenario &s) -> double & { return s.gentleSpeed; })}},
        {QCoreApplication::translate("learnid::ScenarioFields", "Controller"),
         {vector(QStringLiteral("controller.kp"), QStringLiteral("kp"), QStringLiteral("N m/rad"),
                 [](Scenario &s) -> Eigen::VectorXd & { return s.controller.kp; }),
          vector(QStringLiteral("controller.ki"), QStringLiteral("ki"),
                 QStringLiteral("N m/(rad s)"),
                 [](Scenario &s) -> Eigen::VectorXd & { return s.controller.ki; }),
          vector(QStringLiteral("controller.kd"), QStringLiteral("kd"), QStringLiteral("N m s/rad"),
                 [](Scenario &s) -> Eigen::VectorXd & { return s.controller.kd; }),
          number(
              QStringLiteral("controller.lambda"),
              QCoreApplication::translate("learnid::ScenarioFields", "lambda (derivative filter)"),
              QStringLiteral("rad/s"),
              [](Scenario &s) -> double & { return s.controller.lambda; })}},
        {QCoreApplication::translate("learnid::ScenarioFields", "Estimator"),
         {number(QStringLiteral("estimator.rho"),
                 QCoreApplication::translate("learnid::ScenarioFields", "rho (filter F)"),
                 QStringLiteral("rad/s"), [](Scenario &s) -> double & { return s.estimator.rho; }),
          number(QStringLiteral("estimator.rankTolerance"),
                 label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Rank tolerance")), QString(),
                 [](Scenario &s) -> double & { return s.estimator.rankTolerance; }),
          trials,
          integer<int>(QStringLiteral("estimator.repetitions"),
                       label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Repetitions per trial")),
                       [](Scenario &s) -> int & { return s.repetitions; }),
          number(QStringLiteral("estimator.torqueSensorLag"),
                 label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Torque sensor lag")),
                 QStringLiteral("s"),
                 [](Scenario &s) -> double & { return s.estimator.torqueSensorLag; }),
          initial}},
        {label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Safety")),
         {number(QStringLiteral("safety.maxTrackingErrorDeg"),
                 label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Abort at tracking error")),
                 QStringLiteral("deg"),
                 [](Scenario &s) -> double & { return s.maxTrackingErrorDeg; }),
          number(QStringLiteral("safety.stabilityMargin"),
                 label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Required stability margin")),
                 QStringLiteral("1/s"),
                 [](Scenario &s) -> double & { return s.stabilityMargin; })}},
        {label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Simulated robot")),
         {truth,
          number(
              QStringLiteral("simulation.inertiaPerturbation"),
              label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "CAD perturbation (URDF robots)")),
              QString(), [](Scenario &s) -> double & { return s.simulation.inertiaPerturbation; }),
          integer<qint64>(QStringLiteral("simulation.encoderCounts"),
                          label(QT_TRANSLATE_NOOP("learnid::ScenarioFields",
                                                  "Encoder counts per revolution (0: ideal)")),
                          [](Scenario &s) -> qint64 & { return s.simulation.encoderCounts; }),
          number(QStringLiteral("simulation.torqueNoise"),
                 label(QT_TRANSLATE_NOOP("learnid::ScenarioFields",
                                         "Torque noise (fraction of limit)")),
                 QString(), [](Scenario &s) -> double & { return s.simulation.torqueNoise; }),
          integer<quint64>(QStringLiteral("simulation.seed"),
                           label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "Noise seed")),
                           [](Scenario &s) -> quint64 & { return s.simulation.seed; }),
          integer<int>(QStringLiteral("simulation.substeps"),
                       label(QT_TRANSLATE_NOOP("learnid::ScenarioFields", "RK4 steps per sample")),
                       [](Scenario &s) -> int & { return s.simulation.substeps; })}},
    };
}

std::optional<Eigen::VectorXd> parseNumberList(const QString &text, QString *error)
{
    static const QRegularExpression separator(QStringLiteral("[,;\\s]+"));
    const QStringList parts = text.trimmed().split(separator, Qt::SkipEmptyParts);
    if (parts.isEmpty()) {
        *error = QCoreApplication::translate("learnid::ScenarioFields", "enter a value");
        return std::nullopt;
    }
    Eigen::VectorXd values(parts.size());
    for (int i = 0; i < parts.size(); ++i) {
        bool ok = false;
        const double v = parts.at(i).toDouble(&ok); // QString::toDouble uses the C locale
        if (!ok || !std::isfinite(v)) {
            *error =
                QCoreApplication::translate("learnid::ScenarioFields", "\"%1\" is not a number")
                    .arg(parts.at(i));
            return std::nullopt;
        }
        values[i] = v;
    }
    return values;
}

QString formatNumberList(const Eigen::VectorXd &values)
{
    QStringList parts;
    for (Eigen::Index i = 0; i < values.size(); ++i)
        parts << QString::number(values[i], 'g', 12);
    return parts.join(QStringLiteral(", "));
}

bool keyBelongsTo(const QString &errorKey, const QString &fieldKey)
{
    if (!errorKey.startsWith(fieldKey))
        return false;
    if (errorKey.size() == fieldKey.size())
        return true;
    const QChar next = errorKey.at(fieldKey.size());
    return next == QLatin1Char('[') || next == QLatin1Char('.');
}

} // namespace learnid
