#include "io/RobotLogCsv.h"

#include "io/AtomicFile.h"
#include "io/CsvPlace.h"
#include "io/JsonReader.h"
#include "io/ValueChecks.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QHash>
#include <algorithm>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

using csv::fieldPlace;
using csv::quoted;
using csv::throwAtField;
using csv::throwAtLine;

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(RobotLogCsv)
};

constexpr int minimumSamples = 4;
constexpr int listedHeaderNames = 12; // a longer header is shortened in messages

QString columnName(const QString &pattern, int joint)
{
    return QString(pattern).replace(QStringLiteral("%1"), QString::number(joint));
}

// The header's names for messages; a long header (the pendulum's has 15) is cut short.
QString headerList(const QList<QByteArray> &names)
{
    QStringList shown;
    const int count = int(names.size());
    const int listed = count <= listedHeaderNames ? count : listedHeaderNames - 2;
    for (int c = 0; c < listed; ++c)
        shown << (names.at(c).isEmpty() ? QStringLiteral("\"\"")
                                        : QString::fromUtf8(names.at(c).left(40)));
    QString text = shown.join(QStringLiteral(", "));
    if (listed < count)
        text += Text::tr(", ... (%1 columns)").arg(count);
    return text;
}

// Where the values of a sample come from: per value (t, q1..qn, [dq1..dqn], tau1..taun) its
// field, and the magnitude beyond which a revolute joint's value looks like degrees.
struct Layout
{
    struct Entry
    {
        int field;
        double limit;
        bool velocity;
    };
    QList<Entry> entries;
    bool hasVelocities = false;
};

class HeaderReader
{
public:
    HeaderReader(const QString &source, int line, const QByteArray &text)
        : m_source(source)
        , m_line(line)
    {
        m_names = text.split(',');
        for (int c = 0; c < int(m_names.size()); ++c) {
            m_names[c] = m_names[c].trimmed();
            if (m_names[c].isEmpty())
                continue;
            const int first = m_index.value(m_names[c], -1);
            if (first >= 0) {
                throwAtField(m_source, m_line, c + 1, m_names[c],
                             Text::tr("the name repeats that of column %1; each column name may "
                                      "appear only once")
                                 .arg(first + 1));
            }
            m_index.insert(m_names[c], c);
        }
    }
    const QList<QByteArray> &names() const { return m_names; }
    int find(const QString &name) const { return m_index.value(name.toUtf8(), -1); }
    int require(const QString &name, const QString &what) const
    {
        const int c = find(name);
        if (c < 0) {
            throwAtLine(m_source, m_line,
                        Text::tr("no column \"%1\" (%2); the header has: %3")
                            .arg(name, what, headerList(m_names)));
        }
        return c;
    }
    [[noreturn]] void fail(const QString &what) const { throwAtLine(m_source, m_line, what); }

private:
    QString m_source;
    int m_line;
    QList<QByteArray> m_names;
    QHash<QByteArray, int> m_index;
};

// The position columns must be those of exactly `joints` joints: q1..qn, no q(n+1).
void checkJointCount(const HeaderReader &header, const QString &pattern, int joints)
{
    int logJoints = 0;
    while (logJoints < int(header.names().size()) &&
           header.find(columnName(pattern, logJoints + 1)) >= 0)
        ++logJoints;
    bool fewer = logJoints > 0 && logJoints < joints;
    for (int j = logJoints + 1; fewer && j <= joints; ++j)
        fewer = header.find(columnName(pattern, j)) < 0; // not just one column missing
    if (logJoints > joints || fewer) {
        header.fail(Text::tr("the log has %1 joints (%2..%3), the robot %4")
                        .arg(QString::number(logJoints), columnName(pattern, 1),
                             columnName(pattern, logJoints), QString::number(joints)));
    }
}

Layout readLayout(const HeaderReader &header, int joints, const LogColumns &columns,
                  const QList<bool> &angular)
{
    constexpr double none = std::numeric_limits<double>::infinity();
    Layout layout;
    layout.entries << Layout::Entry{header.require(columns.time, Text::tr("the time [s]")), none,
                                    false};
    checkJointCount(header, columns.position, joints);
    const auto limit = [&](int j, double angularLimit) {
        return !angular.isEmpty() && angular.at(j - 1) ? angularLimit : none;
    };
    for (int j = 1; j <= joints; ++j) {
        layout.entries << Layout::Entry{header.require(columnName(columns.position, j),
                                                       Text::tr("the position of joint %1").arg(j)),
                                        limit(j, maxLoggedAngle), false};
    }
    for (int j = 1; !columns.velocity.isEmpty() && j <= joints; ++j)
        layout.hasVelocities |= header.find(columnName(columns.velocity, j)) >= 0;
    for (int j = 1; layout.hasVelocities && j <= joints; ++j) {
        const QString what =
            Text::tr("the velocity of joint %1, as the log has velocities of other joints").arg(j);
        layout.entries << Layout::Entry{header.require(columnName(columns.velocity, j), what),
                                        limit(j, maxLoggedAngularVelocity), true};
    }
    for (int j = 1; j <= joints; ++j) {
        layout.entries << Layout::Entry{header.require(columnName(columns.torque, j),
                                                       Text::tr("the torque of joint %1").arg(j)),
                                        none, false};
    }
    return layout;
}

// The names a caller or --columns gave (prefix: which): a time column, and %1 in each pattern.
void checkColumns(const LogColumns &columns, const QString &prefix)
{
    if (columns.time.isEmpty())
        throw Error(Text::tr("%1: t= names no column; the time column is needed").arg(prefix));
    const std::pair<const char *, const QString *> patterns[] = {
        {"q", &columns.position}, {"dq", &columns.velocity}, {"tau", &columns.torque}};
    for (const auto &[key, pattern] : patterns) {
        if (pattern->contains(QStringLiteral("%1")) ||
            (pattern->isEmpty() && pattern == &columns.velocity))
            continue;
        throw Error(Text::tr("%1: %2=%3 has no %4 where the joint number goes, e.g. %2=%3%4")
                        .arg(prefix, QLatin1String(key), *pattern, QStringLiteral("%1")));
    }
}

} // namespace

LogColumns parseLogColumns(const QString &spec)
{
    const QString option = QStringLiteral("--columns");
    LogColumns columns;
    QStringList seen;
    for (const QString &raw : spec.split(QLatin1Char(','))) {
        const QString entry = raw.trimmed();
        const qsizetype eq = entry.indexOf(QLatin1Char('='));
        if (eq < 0) {
            throw Error(Text::tr("%1: \"%2\" has no '='; expected key=pattern with the keys t, "
                                 "q, dq and tau, e.g. q=pos_meas%3")
                            .arg(option, entry, QStringLiteral("%1")));
        }
        const QString key = entry.left(eq).trimmed();
        QString *target = key == QLatin1String("t")     ? &columns.time
                          : key == QLatin1String("q")   ? &columns.position
                          : key == QLatin1String("dq")  ? &columns.velocity
                          : key == QLatin1String("tau") ? &columns.torque
                                                        : nullptr;
        if (!target) {
            throw Error(Text::tr("%1: unknown key \"%2\"; the keys are t, q, dq and tau")
                            .arg(option, key.left(40)));
        }
        if (seen.contains(key))
            throw Error(Text::tr("%1: the key %2 is given twice").arg(option, key));
        seen << key;
        *target = entry.mid(eq + 1).trimmed();
    }
    checkColumns(columns, option);
    return columns;
}

RobotLog readRobotLog(const QByteArray &csv, const QString &source, int joints,
                      const LogColumns &columns, const QList<bool> &angular, StaleRows stale)
{
    if (joints < 1)
        throw Error(Text::tr("%1: a log is read for 1 joint or more, not %2")
                        .arg(source, QString::number(joints)));
    if (!angular.isEmpty() && int(angular.size()) != joints) {
        throw Error(Text::tr("%1: %2 joint kinds given for a robot of %3 joints")
                        .arg(source, QString::number(angular.size()), QString::number(joints)));
    }
    checkColumns(columns, source);

    QList<QByteArray> lines = csv.split('\n');
    if (!lines.isEmpty() && lines.first().startsWith("\xEF\xBB\xBF"))
        lines.first().remove(0, 3); // UTF-8 byte order mark

    RobotLog log;
    log.source = source;
    QList<QByteArray> names;
    Layout layout;
    int headerLine = 0;
    std::vector<double> values; // sample after sample: t, q1..qn, [dq1..dqn], tau1..taun
    std::vector<double> row;
    std::vector<double> lastRead; // the last row read (kept, stale or repeated): t, values
    int lastLine = 0;
    for (int i = 0; i < int(lines.size()); ++i) {
        const int lineNumber = i + 1;
        QByteArray line = lines.at(i);
        if (line.endsWith('\r'))
            line.chop(1);
        const QByteArray trimmed = line.trimmed();
        if (trimmed.isEmpty() || trimmed.startsWith('#'))
            continue;
        if (names.isEmpty()) {
            const HeaderReader header(source, lineNumber, line);
            layout = readLayout(header, joints, columns, angular);
            names = header.names();
            headerLine = lineNumber;
            continue;
        }
        const QList<QByteArray> fields = line.split(',');
        if (fields.size() != names.size()) {
            const int column = int(std::min(fields.size(), names.size())) + 1;
            throwAtField(source, lineNumber, column, names.value(column - 1),
                         Text::tr("expected %1 fields (%2), got %3")
                             .arg(QString::number(names.size()), headerList(names),
                                  QString::number(fields.size())));
        }
        row.clear();
        for (const Layout::Entry &entry : layout.entries) {
            const int c = entry.field;
            const QByteArray field = fields.at(c).trimmed();
            bool ok = false;
            const double v = field.toDouble(&ok);
            if (!ok) {
                throwAtField(source, lineNumber, c + 1, names.at(c),
                             field.isEmpty() ? Text::tr("the field is empty; expected a number")
                                             : Text::tr("not a number: %1").arg(quoted(field)));
            }
            checkFinite(fieldPlace(source, lineNumber, c + 1, names.at(c)), v);
            if (std::abs(v) > entry.limit) {
                throwAtField(source, lineNumber, c + 1, names.at(c),
                             entry.velocity ? Text::tr("%1 rad/s is faster than any robot joint "
                                                       "turns (at most %2 rad/s); the log looks "
                                                       "like it holds degrees per second, radians "
                                                       "per second are expected")
                                                  .arg(describeNumber(v))
                                                  .arg(maxLoggedAngularVelocity)
                                            : Text::tr("%1 rad is more than 1.05 turns (%2 rad); "
                                                       "the log looks like it holds degrees, "
                                                       "radians are expected")
                                                  .arg(describeNumber(v),
                                                       QString::number(maxLoggedAngle, 'f', 2)));
            }
            row.push_back(v);
        }
        if (!lastRead.empty()) {
            // Compared with the last row read, kept or not: a stale or repeated row has the
            // values of the last sample kept, and its time stamp still orders the rows.
            const int tc = layout.entries.first().field;
            if (row.front() < lastRead.front()) {
                throwAtField(source, lineNumber, tc + 1, names.at(tc),
                             Text::tr("the times must increase from sample to sample, got %1 "
                                      "after %2 on line %3")
                                 .arg(describeNumber(row.front()), describeNumber(lastRead.front()))
                                 .arg(lastLine));
            }
            const auto differs = std::mismatch(row.begin() + 1, row.end(), lastRead.begin() + 1);
            if (row.front() == lastRead.front()) {
                if (differs.first == row.end()) {
                    ++log.repeatedSamples; // the logger wrote the sample twice
                    continue;
                }
                const int dc = layout.entries.at(int(differs.first - row.begin())).field;
                throwAtField(source, lineNumber, tc + 1, names.at(tc),
                             Text::tr("the time %1 repeats that of line %2 with other values "
                                      "(%3: %4 there, %5 here); only an exact repeat of a row is "
                                      "dropped")
                                 .arg(describeNumber(row.front()))
                                 .arg(lastLine)
                                 .arg(QString::fromUtf8(names.at(dc)),
                                      describeNumber(*differs.second),
                                      describeNumber(*differs.first)));
            }
            if (differs.first == row.end() && stale == StaleRows::Drop) {
                log.staleRows.push_back(lineNumber); // old values under a new time stamp
                lastRead.front() = row.front();
                lastLine = lineNumber;
                continue;
            }
        }
        lastRead = row;
        lastLine = lineNumber;
        values.insert(values.end(), row.begin(), row.end());
        log.rows.push_back(lineNumber);
    }
    const int endLine = int(lines.size()) + (lines.isEmpty() || !lines.last().isEmpty() ? 1 : 0);
    if (names.isEmpty()) {
        const QString expected =
            QStringLiteral("%1, %2..%3, %4..%5")
                .arg(columns.time, columnName(columns.position, 1),
                     columnName(columns.position, joints), columnName(columns.torque, 1),
                     columnName(columns.torque, joints));
        throwAtLine(source, endLine,
                    Text::tr("the file holds no header line; expected one naming the columns %1")
                        .arg(expected));
    }
    const int width = int(layout.entries.size());
    const int samples = int(log.rows.size());
    if (samples < minimumSamples) {
        const QString stale =
            log.staleRows.empty()
                ? QString()
                : Text::tr(" (and %n stale row(s): values repeated under a new time stamp, "
                           "treated as missing)",
                           nullptr, log.staleSamples());
        throwAtLine(source, endLine,
                    Text::tr("%1 samples after the header on line %2%3; a log needs at least %4")
                        .arg(samples)
                        .arg(headerLine)
                        .arg(stale)
                        .arg(minimumSamples));
    }
    const Eigen::Map<const Eigen::MatrixXd> table(values.data(), width, samples);
    log.t = table.row(0).transpose();
    log.q = table.middleRows(1, joints);
    if (layout.hasVelocities)
        log.dq = table.middleRows(1 + joints, joints);
    log.tau = table.bottomRows(joints);
    return log;
}

RobotLog readRobotLogFile(const QString &path, int joints, const LogColumns &columns,
                          const QList<bool> &angular)
{
    return readRobotLog(readFile(path), QDir::toNativeSeparators(path), joints, columns, angular);
}

} // namespace learnid
