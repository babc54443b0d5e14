#include "io/TrialCsv.h"

#include "io/AtomicFile.h"
#include "io/CsvPlace.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QList>
#include <QLocale>
#include <cmath>

namespace learnid {

namespace {

using csv::throwAtLine;

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(TrialCsv)
};

constexpr double degPerRad = 180.0 / M_PI;
constexpr int columnsPerJoint = 5;

QByteArray number(double v)
{
    return QByteArray::number(v, 'g', QLocale::FloatingPointShortest);
}

QList<QByteArray> header(int dof)
{
    QList<QByteArray> h{QByteArrayLiteral("t_s")};
    for (int j = 1; j <= dof; ++j) {
        const QByteArray n = QByteArray::number(j);
        h << "qd" + n + "_rad"
          << "q" + n + "_rad"
          << "e" + n + "_deg"
          << "tauf" + n + "_Nm"
          << "tau" + n + "_Nm";
    }
    return h;
}

} // namespace

QByteArray trialCsv(const TrialPlan &plan, const TrialRecord &record)
{
    const int n = plan.desired.dof();
    const int samples = record.samples();
    if (record.q.rows() != n || record.tau.rows() != n || record.tau.cols() != samples ||
        plan.feedforward.rows() != n || plan.feedforward.cols() != plan.samples() ||
        samples > plan.samples()) {
        throw Error(Text::tr("trial CSV: the record (%1 joints, %2 samples) does not fit its plan "
                             "(%3 joints, %4 samples)")
                        .arg(record.q.rows())
                        .arg(samples)
                        .arg(n)
                        .arg(plan.samples()));
    }
    QByteArray out = header(n).join(',') + '\n';
    out.reserve(out.size() + qsizetype(samples) * (1 + columnsPerJoint * n) * 20);
    for (int k = 0; k < samples; ++k) {
        out += number(k * record.samplePeriod);
        for (int j = 0; j < n; ++j) {
            const double qd = plan.desired.q(j, k);
            const double q = record.q(j, k);
            out += ',' + number(qd) + ',' + number(q) + ',' + number((qd - q) * degPerRad) + ',' +
                   number(plan.feedforward(j, k)) + ',' + number(record.tau(j, k));
        }
        out += '\n';
    }
    return out;
}

TrialRecord TrialRecordCsv::record() const
{
    TrialRecord r;
    r.samplePeriod = samplePeriod();
    r.q = q;
    r.tau = tau;
    return r;
}

TrialRecordCsv readTrialCsv(const QByteArray &csv, const QString &sourceName)
{
    QList<QByteArray> lines = csv.split('\n');
    while (!lines.isEmpty() && lines.constLast().trimmed().isEmpty())
        lines.removeLast(); // the final newline
    if (lines.isEmpty())
        throwAtLine(sourceName, 1, Text::tr("the file is empty; expected the header line"));
    for (QByteArray &line : lines) {
        if (line.endsWith('\r'))
            line.chop(1);
    }

    const QList<QByteArray> names = lines.constFirst().split(',');
    const int n = int(names.size() - 1) / columnsPerJoint;
    if (names.size() < 1 + columnsPerJoint || (names.size() - 1) % columnsPerJoint != 0 ||
        names != header(n)) {
        throwAtLine(sourceName, 1,
                    Text::tr("the header must be %1 (for one or more joints), got %2")
                        .arg(QString::fromUtf8(header(1).join(',')) + QStringLiteral(",..."),
                             QString::fromUtf8(lines.constFirst().left(120))));
    }

    const int samples = int(lines.size()) - 1;
    TrialRecordCsv r;
    r.t.resize(samples);
    for (Eigen::MatrixXd *m : {&r.qDesired, &r.q, &r.trackingErrorDeg, &r.feedforward, &r.tau})
        m->resize(n, samples);
    for (int k = 0; k < samples; ++k) {
        const int lineNumber = k + 2;
        const QList<QByteArray> fields = lines.at(k + 1).split(',');
        if (fields.size() != names.size()) {
            throwAtLine(
                sourceName, lineNumber,
                Text::tr("expected %1 fields, got %2").arg(names.size()).arg(fields.size()));
        }
        Eigen::VectorXd row(fields.size());
        for (int c = 0; c < int(fields.size()); ++c) {
            bool ok = false;
            row[c] = fields.at(c).trimmed().toDouble(&ok);
            if (!ok) {
                throwAtLine(sourceName, lineNumber,
                            Text::tr("%1 is not a number: \"%2\"")
                                .arg(QString::fromLatin1(names.at(c)),
                                     QString::fromUtf8(fields.at(c).left(40))));
            }
        }
        if (!std::isfinite(row[0]) || (k > 0 && !(row[0] > r.t[k - 1]))) {
            throwAtLine(sourceName, lineNumber,
                        Text::tr("t_s must be finite and increase from line to line, got %1")
                            .arg(QString::fromLatin1(fields.at(0))));
        }
        r.t[k] = row[0];
        for (int j = 0; j < n; ++j) {
            const int c = 1 + columnsPerJoint * j;
            r.qDesired(j, k) = row[c];
            r.q(j, k) = row[c + 1];
            r.trackingErrorDeg(j, k) = row[c + 2];
            r.feedforward(j, k) = row[c + 3];
            r.tau(j, k) = row[c + 4];
        }
    }
    return r;
}

TrialRecordCsv readTrialCsvFile(const QString &path)
{
    return readTrialCsv(readFile(path), QDir::toNativeSeparators(path));
}

} // namespace learnid
