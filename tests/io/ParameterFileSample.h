#pragma once

// A filled ParameterFileContent for the parameter file and DCF tests.

#include "io/ParameterFile.h"
#include "model/ModelFactory.h"

#include <limits>

namespace learnid::test {

inline ParameterFileContent sampleParameterFile()
{
    ParameterFileContent c;
    c.robotModel = QStringLiteral("paper-2link");
    c.robotDescription =
        QStringLiteral("simulated paper-2link (2^20 counts/rev, 1 % torque noise)");
    c.created = QDateTime(QDate(2024, 5, 1), QTime(12, 34, 56, 789), Qt::UTC);
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.law = QStringLiteral("improved");
    c.sourceTrial = 2;
    c.parameters = makeRobotModel(c.robotModel)->parameters();
    c.values = Eigen::Vector3d(20.000123456789012, 1.0 / 3.0, 7.9999999999999991);
    c.standardDeviations = Eigen::Vector3d(0.0123, std::numeric_limits<double>::infinity(), 2.5e-7);
    c.maxTrackingErrorDeg = Eigen::Vector2d(0.039, 0.0017999999999999999);
    c.rmsTrackingErrorDeg = Eigen::Vector2d(0.011, 0.0004);
    c.residualRms = Eigen::Vector2d(0.0031, 0.0029);
    c.condition = 37.8;
    c.rank = 2;
    c.canWrites.append(
        {1, 0x2100, 1, QStringLiteral("REAL32"), 4500.0, QByteArray::fromHex("00a08c45")});
    c.canWrites.append(
        {2, 0x2200, 3, QStringLiteral("REAL32"), 8.0, QByteArray::fromHex("00000041")});
    c.canWrites.append({1, 0x1010, 1, QStringLiteral("UNSIGNED32"), 1702257011.0,
                        QByteArray::fromHex("73617665")});
    return c;
}

} // namespace learnid::test
