#include "io/PlanCsv.h"

#include "io/AtomicFile.h"
#include "io/CsvPlace.h"
#include "io/JsonReader.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QLocale>
#include <QRegularExpression>
#include <cmath>
#include <optional>

namespace learnid {

namespace {

using csv::quoted;
using csv::throwAtField;
using csv::throwAtLine;

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PlanCsv)
};

// Shortest round-trip form; -0 keeps its sign (QByteArray::number writes 0), so that a plan
// reads back bit for bit.
QByteArray number(double v)
{
    if (v == 0.0 && std::signbit(v))
        return QByteArrayLiteral("-0");
    return QByteArray::number(v, 'g', QLocale::FloatingPointShortest);
}

QList<QByteArray> headerNames(int joints)
{
    QList<QByteArray> names{QByteArrayLiteral("t")};
    for (int j = 1; j <= joints; ++j)
        names << "qd" + QByteArray::number(j);
    for (int j = 1; j <= joints; ++j)
        names << "tauf" + QByteArray::number(j);
    return names;
}

// A finite number, or nullopt.
std::optional<double> finiteNumber(const QByteArray &field)
{
    bool ok = false;
    const double v = field.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

// The file's lines without their \r, the final empty piece after the last \n dropped.
QList<QByteArray> splitLines(const QByteArray &csv)
{
    QList<QByteArray> lines = csv.split('\n');
    if (!lines.isEmpty() && lines.constLast().isEmpty())
        lines.removeLast();
    if (!lines.isEmpty() && lines.first().startsWith("\xEF\xBB\xBF"))
        lines.first().remove(0, 3); // UTF-8 byte order mark
    for (QByteArray &line : lines) {
        if (line.endsWith('\r'))
            line.chop(1);
    }
    return lines;
}

// "# key: value" -> (key, value); a comment line without "key:" gives an empty key.
std::pair<QByteArray, QByteArray> commentEntry(const QByteArray &line)
{
    const QByteArray body = line.trimmed().mid(1).trimmed();
    const qsizetype colon = body.indexOf(':');
    static const QRegularExpression keyPattern(QStringLiteral("^[a-z][a-z-]*$"));
    if (colon < 0 || !keyPattern.match(QString::fromLatin1(body.left(colon))).hasMatch())
        return {};
    return {body.left(colon), body.mid(colon + 1).trimmed()};
}

bool isPlanId(const QByteArray &text)
{
    static const QRegularExpression hex(QStringLiteral("^[0-9a-fA-F]{64}$"));
    return hex.match(QString::fromLatin1(text)).hasMatch();
}

struct Comments
{
    QByteArray planId, robot, samplePeriod, estimate;
    int planIdLine = 0, robotLine = 0, samplePeriodLine = 0, estimateLine = 0;
};

void readComment(const QString &source, int lineNumber, const QByteArray &line, Comments &c)
{
    const auto [key, value] = commentEntry(line);
    const std::pair<const char *, std::pair<QByteArray *, int *>> known[] = {
        {"plan-id", {&c.planId, &c.planIdLine}},
        {"robot", {&c.robot, &c.robotLine}},
        {"sample-period", {&c.samplePeriod, &c.samplePeriodLine}},
        {"estimate", {&c.estimate, &c.estimateLine}}};
    for (const auto &[name, target] : known) {
        if (key != name)
            continue;
        if (*target.second > 0)
            throwAtLine(source, lineNumber,
                        Text::tr("a second \"# %1:\" line; the first is on line %2")
                            .arg(QLatin1String(name))
                            .arg(*target.second));
        *target.first = value;
        *target.second = lineNumber;
    }
}

// What the comment lines say: the plan's id, robot, sample period and estimate.
PlanCsv planOfComments(const QString &source, const Comments &c, int headerLine, int *joints)
{
    const std::pair<const char *, int> required[] = {{"plan-id", c.planIdLine},
                                                     {"robot", c.robotLine},
                                                     {"sample-period", c.samplePeriodLine},
                                                     {"estimate", c.estimateLine}};
    for (const auto &[name, line] : required) {
        if (line == 0)
            throwAtLine(source, headerLine,
                        Text::tr("no \"# %1:\" line before the header").arg(QLatin1String(name)));
    }

    PlanCsv plan;
    if (!isPlanId(c.planId))
        throwAtLine(
            source, c.planIdLine,
            Text::tr("the plan-id must be 64 hex digits (SHA-256), got %1").arg(quoted(c.planId)));
    plan.planId = QString::fromLatin1(c.planId).toLower();
    static const QRegularExpression robotPattern(QStringLiteral("^(.+),\\s*(\\d{1,4}) joints?$"));
    const QRegularExpressionMatch robot = robotPattern.match(QString::fromUtf8(c.robot));
    *joints = robot.hasMatch() ? robot.captured(2).toInt() : 0;
    if (*joints < 1)
        throwAtLine(
            source, c.robotLine,
            Text::tr("expected \"# robot: <model>, <n> joints\", got %1").arg(quoted(c.robot)));
    plan.robotModel = robot.captured(1).trimmed();
    const std::optional<double> ts = finiteNumber(c.samplePeriod);
    if (!ts || *ts <= 0.0)
        throwAtLine(source, c.samplePeriodLine,
                    Text::tr("the sample period must be a positive number [s], got %1")
                        .arg(quoted(c.samplePeriod)));
    plan.samplePeriod = *ts;
    const QList<QByteArray> estimate = c.estimate.split(',');
    plan.estimate.resize(estimate.size());
    for (int i = 0; i < int(estimate.size()); ++i) {
        const std::optional<double> v = finiteNumber(estimate.at(i));
        if (!v)
            throwAtLine(source, c.estimateLine,
                        Text::tr("estimate value %1 is not a finite number: %2")
                            .arg(i + 1)
                            .arg(quoted(estimate.at(i))));
        plan.estimate[i] = *v;
    }

    return plan;
}

} // namespace

QString planIdOfData(const QByteArray &dataLines)
{
    return QString::fromLatin1(
        QCryptographicHash::hash(dataLines, QCryptographicHash::Sha256).toHex());
}

namespace {

// The lines from the header on, each ended by \n.
QByteArray planData(const TrialPlan &plan)
{
    const int n = plan.desired.dof();
    const int samples = plan.samples();
    if (n < 1 || samples < 1 || plan.feedforward.rows() != n ||
        plan.feedforward.cols() != samples || !(plan.desired.samplePeriod > 0.0) ||
        !plan.desired.q.allFinite() || !plan.feedforward.allFinite()) {
        throw Error(Text::tr("plan CSV: the plan (%1 joints, %2 samples, %3 feedforward columns) "
                             "is empty, does not fit its feedforward or holds non-finite numbers")
                        .arg(n)
                        .arg(samples)
                        .arg(plan.feedforward.cols()));
    }
    QByteArray out = headerNames(n).join(',') + '\n';
    out.reserve(out.size() + qsizetype(samples) * (1 + 2 * n) * 20);
    for (int k = 0; k < samples; ++k) {
        out += number(k * plan.desired.samplePeriod);
        for (int j = 0; j < n; ++j)
            out += ',' + number(plan.desired.q(j, k));
        for (int j = 0; j < n; ++j)
            out += ',' + number(plan.feedforward(j, k));
        out += '\n';
    }
    return out;
}

} // namespace

QString planIdOf(const TrialPlan &plan)
{
    return planIdOfData(planData(plan));
}

QByteArray planCsv(const TrialPlan &plan, const QString &robotModel)
{
    const QByteArray data = planData(plan);
    if (plan.feedforwardParameters.size() < 1 || !plan.feedforwardParameters.allFinite())
        throw Error(Text::tr("plan CSV: the estimate the feedforward was built with is empty or "
                             "not finite"));
    QList<QByteArray> estimate;
    for (Eigen::Index i = 0; i < plan.feedforwardParameters.size(); ++i)
        estimate << number(plan.feedforwardParameters[i]);
    QByteArray out = QByteArray("# ") + planCsvSchema + '\n';
    out += "# plan-id: " + planIdOfData(data).toLatin1() + '\n';
    out += "# robot: " + robotModel.toUtf8() + ", " + QByteArray::number(plan.desired.dof()) +
           (plan.desired.dof() == 1 ? " joint\n" : " joints\n");
    out += "# sample-period: " + number(plan.desired.samplePeriod) + '\n';
    out += "# estimate: " + estimate.join(", ") + '\n';
    return out + data;
}

PlanCsv readPlanCsv(const QByteArray &csv, const QString &source)
{
    const QList<QByteArray> lines = splitLines(csv);
    const QByteArray schemaLine = QByteArray("# ") + planCsvSchema;
    if (lines.isEmpty() || lines.first().trimmed() != schemaLine) {
        throwAtLine(source, 1,
                    Text::tr("not a plan file of this version: the first line must be \"%1\"")
                        .arg(QString::fromLatin1(schemaLine)));
    }
    Comments c;
    int header = 1; // index of the header line
    while (header < lines.size() &&
           (lines.at(header).trimmed().isEmpty() || lines.at(header).trimmed().startsWith('#'))) {
        if (!lines.at(header).trimmed().isEmpty())
            readComment(source, header + 1, lines.at(header), c);
        ++header;
    }
    const int headerLine = header + 1;
    int joints = 0;
    PlanCsv plan = planOfComments(source, c, headerLine, &joints);

    const QList<QByteArray> expected = headerNames(joints);
    if (header >= lines.size())
        throwAtLine(
            source, headerLine,
            Text::tr("no header line; expected %1").arg(QString::fromLatin1(expected.join(','))));
    const QList<QByteArray> names = lines.at(header).split(',');
    for (int col = 0; col < int(std::max(names.size(), expected.size())); ++col) {
        const QByteArray got = col < names.size() ? names.at(col).trimmed() : QByteArray();
        if (col >= expected.size() || got != expected.at(col)) {
            throwAtField(source, headerLine, col + 1, got,
                         Text::tr("the header of a plan of %1 joints is %2")
                             .arg(joints)
                             .arg(QString::fromLatin1(expected.join(','))));
        }
    }
    const int samples = int(lines.size()) - header - 1;
    if (samples < 1)
        throwAtLine(source, headerLine + 1, Text::tr("no samples after the header"));
    plan.t.resize(samples);
    plan.qDesired.resize(joints, samples);
    plan.feedforward.resize(joints, samples);
    QByteArray data = lines.at(header) + '\n';
    for (int k = 0; k < samples; ++k) {
        const int lineNumber = headerLine + 1 + k;
        const QByteArray &line = lines.at(header + 1 + k);
        if (line.trimmed().isEmpty() || line.trimmed().startsWith('#'))
            throwAtLine(source, lineNumber,
                        Text::tr("a blank or comment line among the samples; comments go before "
                                 "the header"));
        data += line + '\n';
        const QList<QByteArray> fields = line.split(',');
        if (fields.size() != expected.size()) {
            const int column = int(std::min(fields.size(), expected.size())) + 1;
            throwAtField(
                source, lineNumber, column, expected.value(column - 1),
                Text::tr("expected %1 fields, got %2").arg(expected.size()).arg(fields.size()));
        }
        for (int col = 0; col < int(fields.size()); ++col) {
            const std::optional<double> v = finiteNumber(fields.at(col));
            if (!v)
                throwAtField(source, lineNumber, col + 1, expected.at(col),
                             Text::tr("not a finite number: %1").arg(quoted(fields.at(col))));
            if (col == 0) {
                if (*v != k * plan.samplePeriod)
                    throwAtField(
                        source, lineNumber, 1, expected.at(0),
                        Text::tr("sample %1 is at k Ts = %2 s, got %3 s")
                            .arg(k)
                            .arg(describeNumber(k * plan.samplePeriod), describeNumber(*v)));
                plan.t[k] = *v;
            } else if (col <= joints) {
                plan.qDesired(col - 1, k) = *v;
            } else {
                plan.feedforward(col - 1 - joints, k) = *v;
            }
        }
    }
    const QString computed = planIdOfData(data);
    if (computed != plan.planId)
        throwAtLine(source, c.planIdLine,
                    Text::tr("the plan-id %1 is not that of the plan's numbers (%2): the plan was "
                             "changed after learnid wrote it")
                        .arg(plan.planId, computed));
    return plan;
}

PlanCsv readPlanCsvFile(const QString &path)
{
    return readPlanCsv(readFile(path), QDir::toNativeSeparators(path));
}

QString planIdLine(const QByteArray &csv, const QString &source)
{
    const QList<QByteArray> lines = splitLines(csv);
    QString id;
    int idLine = 0;
    for (int i = 0; i < int(lines.size()); ++i) {
        if (!lines.at(i).trimmed().startsWith('#'))
            continue;
        const auto [key, value] = commentEntry(lines.at(i));
        if (key != "plan-id")
            continue;
        if (!isPlanId(value))
            throwAtLine(
                source, i + 1,
                Text::tr("the plan-id must be 64 hex digits (SHA-256), got %1").arg(quoted(value)));
        const QString found = QString::fromLatin1(value).toLower();
        if (!id.isEmpty() && found != id)
            throwAtLine(source, i + 1,
                        Text::tr("a second plan-id, %1, other than %2 on line %3; a log is of "
                                 "one plan")
                            .arg(found, id)
                            .arg(idLine));
        if (id.isEmpty()) {
            id = found;
            idLine = i + 1;
        }
    }
    return id;
}

} // namespace learnid
