#pragma once

// The fault cases of the end-to-end CAN tests (a robot with 2 joints and one with 7): the rows
// of learnid-robot-sim's fault injection and, from a trial's candump log, when the fault
// happened, so that a test can measure how long the master took to end the trial.

#include "can/CandumpLog.h"

#include <QStringList>
#include <QTest>

namespace learnid::test {

/// Rows faults (learnid-robot-sim options), cliArgs (learnid-cli run options) and expected (in
/// the CLI's error): a dropped TPDO, a silent robot, an EMCY at emcySample, an SDO abort of the
/// first parameter write during apply; the robot goes silent after silentAfter frames.
inline void addCanFaultRows(int emcySample, int silentAfter = 4000)
{
    QTest::addColumn<QStringList>("faults");
    QTest::addColumn<QStringList>("cliArgs");
    QTest::addColumn<QString>("expected");
    const QStringList one{QStringLiteral("--iterations"), QStringLiteral("1")};
    QTest::newRow("drop") << QStringList{QStringLiteral("--drop-fraction"), QStringLiteral("0.02")}
                          << one << QStringLiteral("sample missing");
    QTest::newRow("silent") << QStringList{QStringLiteral("--silent-after"),
                                           QString::number(silentAfter)}
                            << one << QStringLiteral("no SYNC");
    QTest::newRow("emcy") << QStringList{QStringLiteral("--emcy-at-sample"),
                                         QString::number(emcySample)}
                          << one << QStringLiteral("0x8611");
    QTest::newRow("refuse-sdo") << QStringList{QStringLiteral("--refuse-sdo"),
                                               QStringLiteral("0x2200:1")}
                                << one + QStringList{QStringLiteral("--apply")}
                                << QStringLiteral("0x2200:01");
}

/// A frame's time stamp [us].
inline qint64 candumpMicroseconds(const CandumpEntry &e)
{
    return e.frame.timeStamp().seconds() * 1000000 + e.frame.timeStamp().microSeconds();
}

/// When the fault of row tag happened in a trial's log [us], or -1: the EMCY of firstNode; for
/// the others the robot side's last frame before the master's first quick stop (RPDO with
/// controlword 0x0002 to firstNode; the master repeats it at every SYNC until the drives report
/// no power).
inline qint64 faultMicroseconds(const QList<CandumpEntry> &log, const QString &tag,
                                quint32 firstNode)
{
    for (int i = 0; i < log.size(); ++i) {
        const QCanBusFrame &f = log[i].frame;
        if (tag == QLatin1String("emcy") && f.frameId() == 0x80 + firstNode &&
            f.payload().size() >= 2 && f.payload().at(1) != 0)
            return candumpMicroseconds(log[i]);
    }
    if (tag == QLatin1String("emcy"))
        return -1;
    for (int i = 0; i < log.size(); ++i) {
        const QCanBusFrame &f = log[i].frame;
        if (f.frameId() == 0x200 + firstNode && f.payload().size() == 8 && f.payload().at(6) == 2) {
            int j = i - 1;
            while (j >= 0 && (log[j].frame.frameId() & 0x780) == 0x200)
                --j; // skip earlier set-points
            return j >= 0 ? candumpMicroseconds(log[j]) : -1;
        }
    }
    return -1;
}

} // namespace learnid::test
