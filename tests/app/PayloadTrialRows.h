#pragma once
// Test support: the trial rows `learnid-cli run` prints for a payload session (index, max error,
// RMS error, mass, (cx, cy, cz) in mm, update CPU, identified), and the rows of the payload's
// table that `run` and `identify --payload` print after them (value, estimate, std. error).

#include <Eigen/Core>
#include <QList>
#include <QRegularExpression>
#include <QString>
#include <cmath>

namespace learnid::test {

struct PayloadRow
{
    int trial = -1;
    double maxError = 0.0, rmsError = 0.0, mass = 0.0;
    Eigen::Vector3d comMm = Eigen::Vector3d::Zero();
    QString identified;
};

inline QList<PayloadRow> payloadTrialRows(const QString &out)
{
    static const QRegularExpression row(
        QStringLiteral("^\\s+(\\d+)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+\\((\\S+), (\\S+), (\\S+)\\)"
                       "\\s+(\\S+)\\s+(.+)$"),
        QRegularExpression::MultilineOption);
    QList<PayloadRow> rows;
    for (auto it = row.globalMatch(out); it.hasNext();) {
        const auto m = it.next();
        rows.append({m.captured(1).toInt(), m.captured(2).toDouble(), m.captured(3).toDouble(),
                     m.captured(4).toDouble(),
                     Eigen::Vector3d(m.captured(5).toDouble(), m.captured(6).toDouble(),
                                     m.captured(7).toDouble()),
                     m.captured(9).trimmed()});
    }
    return rows;
}

// Column `column` (0: the estimate, 1: its standard error) of the payload table's row whose
// name starts the line ("m [kg]", "cx [m]"); NaN when there is none.
inline double tableNumber(const QString &out, const QString &name, int column)
{
    const QRegularExpression row(QStringLiteral("^%1 \\[[^\\]]*\\](?:\\s+\\S+){%2}\\s+(\\S+)")
                                     .arg(QRegularExpression::escape(name))
                                     .arg(column),
                                 QRegularExpression::MultilineOption);
    const QRegularExpressionMatch m = row.match(out);
    return m.hasMatch() ? m.captured(1).toDouble() : NAN;
}

inline double tableValue(const QString &out, const QString &name)
{
    return tableNumber(out, name, 0);
}

inline double tableStdError(const QString &out, const QString &name)
{
    return tableNumber(out, name, 1);
}

inline QString tableRow(const QString &out, const QString &name)
{
    for (const QString &line : out.split(QLatin1Char('\n')))
        if (line.startsWith(name + QStringLiteral(" [")))
            return line;
    return {};
}

} // namespace learnid::test
