#include "io/PathCsv.h"

#include "io/AtomicFile.h"
#include "io/CsvPlace.h"
#include "io/JsonReader.h"
#include "io/ValueChecks.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QList>
#include <QLocale>
#include <algorithm>
#include <vector>

namespace learnid {

namespace {

using csv::fieldPlace;
using csv::quoted;
using csv::throwAtField;
using csv::throwAtLine;

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PathCsv)
};

constexpr int minimumSamples = 4;

QByteArray number(double v)
{
    return QByteArray::number(v, 'g', QLocale::FloatingPointShortest);
}

QString expectedHeader()
{
    return QStringLiteral("t,q1,...,qn");
}

// The column names of the header line, checked against t,q1,...,qn and expectedJoints.
QList<QByteArray> readHeader(const QByteArray &line, const QString &source, int lineNumber,
                             int expectedJoints)
{
    QList<QByteArray> names = line.split(',');
    for (QByteArray &name : names)
        name = name.trimmed();
    for (int c = 0; c < int(names.size()); ++c) {
        const QByteArray expected = c == 0 ? QByteArrayLiteral("t") : "q" + QByteArray::number(c);
        if (names.at(c) != expected) {
            throwAtField(
                source, lineNumber, c + 1, QByteArray(),
                Text::tr("the header must be %1 (the time, then one column per joint); "
                         "expected %2, got %3")
                    .arg(expectedHeader(), QString::fromLatin1(expected), quoted(names.at(c))));
        }
    }
    if (names.size() < 2) {
        throwAtField(source, lineNumber, 2, QByteArray(),
                     Text::tr("the header must be %1 (the time, then one column per joint); "
                              "the joint columns are missing")
                         .arg(expectedHeader()));
    }
    const int joints = int(names.size()) - 1;
    if (expectedJoints > 0 && joints != expectedJoints) {
        const int column = (joints > expectedJoints ? expectedJoints : joints) + 2;
        throwAtField(source, lineNumber, column, QByteArray(),
                     Text::tr("the header names the joints q1..q%1; the robot has %2 joints")
                         .arg(joints)
                         .arg(expectedJoints));
    }
    return names;
}

} // namespace

PathSamples readPathCsv(const QByteArray &csv, const QString &sourceName, int expectedJoints)
{
    QList<QByteArray> lines = csv.split('\n');
    if (!lines.isEmpty() && lines.first().startsWith("\xEF\xBB\xBF"))
        lines.first().remove(0, 3); // UTF-8 byte order mark

    QList<QByteArray> names;
    int headerLine = 0;
    int previousLine = 0;
    std::vector<double> values; // row after row: t, q1 .. qn
    for (int i = 0; i < int(lines.size()); ++i) {
        const int lineNumber = i + 1;
        QByteArray line = lines.at(i);
        if (line.endsWith('\r'))
            line.chop(1);
        const QByteArray trimmed = line.trimmed();
        if (trimmed.isEmpty() || trimmed.startsWith('#'))
            continue;
        if (names.isEmpty()) {
            names = readHeader(line, sourceName, lineNumber, expectedJoints);
            headerLine = lineNumber;
            continue;
        }
        const QList<QByteArray> fields = line.split(',');
        if (fields.size() != names.size()) {
            const int column = int(std::min(fields.size(), names.size())) + 1;
            throwAtField(sourceName, lineNumber, column, names.value(column - 1),
                         Text::tr("expected %1 fields (%2), got %3")
                             .arg(names.size())
                             .arg(QString::fromUtf8(names.join(',')))
                             .arg(fields.size()));
        }
        for (int c = 0; c < int(fields.size()); ++c) {
            const QByteArray field = fields.at(c).trimmed();
            bool ok = false;
            const double v = field.toDouble(&ok);
            if (!ok) {
                throwAtField(sourceName, lineNumber, c + 1, names.at(c),
                             field.isEmpty() ? Text::tr("the field is empty; expected a number")
                                             : Text::tr("not a number: %1").arg(quoted(field)));
            }
            checkFinite(fieldPlace(sourceName, lineNumber, c + 1, names.at(c)), v);
            if (c == 0 && previousLine > 0 && !(v > values[values.size() - names.size()])) {
                throwAtField(sourceName, lineNumber, 1, names.at(0),
                             Text::tr("the times must increase from sample to sample, got %1 "
                                      "after %2 on line %3")
                                 .arg(describeNumber(v),
                                      describeNumber(values[values.size() - names.size()]))
                                 .arg(previousLine));
            }
            values.push_back(v);
        }
        previousLine = lineNumber;
    }
    const int endLine = int(lines.size()) + (lines.isEmpty() || !lines.last().isEmpty() ? 1 : 0);
    if (names.isEmpty()) {
        throwAtLine(sourceName, endLine,
                    Text::tr("the file holds no header line; expected %1").arg(expectedHeader()));
    }
    const int columns = int(names.size());
    const int samples = int(values.size()) / columns;
    if (samples < minimumSamples) {
        throwAtLine(sourceName, endLine,
                    Text::tr("%1 samples after the header on line %2; a path needs at least %3")
                        .arg(samples)
                        .arg(headerLine)
                        .arg(minimumSamples));
    }
    const Eigen::Map<const Eigen::MatrixXd> table(values.data(), columns, samples);
    PathSamples path;
    path.t = table.row(0).transpose();
    path.q = table.bottomRows(columns - 1);
    return path;
}

PathSamples readPathCsvFile(const QString &path, int expectedJoints)
{
    return readPathCsv(readFile(path), QDir::toNativeSeparators(path), expectedJoints);
}

QByteArray pathCsv(const PathSamples &path)
{
    if (path.t.size() != path.q.cols()) {
        throw Error(Text::tr("path CSV: %1 sample times but %2 samples of the joints")
                        .arg(path.t.size())
                        .arg(path.q.cols()));
    }
    QByteArray out = "t";
    for (int j = 1; j <= path.dof(); ++j)
        out += ",q" + QByteArray::number(j);
    out += '\n';
    for (int k = 0; k < path.samples(); ++k) {
        out += number(path.t[k]);
        for (int j = 0; j < path.dof(); ++j)
            out += ',' + number(path.q(j, k));
        out += '\n';
    }
    return out;
}

} // namespace learnid
