#include "canrobot/NodeConfiguration.h"

#include "can/CanOpen.h"
#include "can/ManufacturerObjects.h"
#include "can/Pdo.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

using canopen::DataType;

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CanRobot)
};

constexpr quint16 positionEncoderResolution = 0x608F;
constexpr quint16 motorRatedTorque = 0x6076;

// A read of an UNSIGNED32 that must be positive; value goes to *target.
SdoStep readPositive(quint8 node, quint16 index, quint8 sub, quint32 *target)
{
    return SdoStep::read(node, index, sub, [node, index, sub, target](const QByteArray &data) {
        if (data.size() < 4)
            return Text::tr("node %1, object %2: the answer holds %3 bytes, UNSIGNED32 needs 4")
                .arg(node)
                .arg(canopen::objectAddress(index, sub))
                .arg(data.size());
        const quint32 v = canopen::readU32(data, 0);
        if (v == 0)
            return Text::tr("node %1, object %2 is 0: the drive's units are unusable")
                .arg(node)
                .arg(canopen::objectAddress(index, sub));
        *target = v;
        return QString();
    });
}

} // namespace

QList<SdoStep> trialConfigurationSteps(const QList<int> &nodes, const TrialPlan &plan,
                                       const CanRobotOptions &options,
                                       std::shared_ptr<NodeConfigurationResult> result)
{
    const int n = int(nodes.size());
    const ControllerSettings &c = plan.controller;
    if (c.kp.size() != n || c.ki.size() != n || c.kd.size() != n || plan.torqueLimit.size() != n)
        throw Error(Text::tr("the plan is for %1 joints but %2 CAN nodes are configured")
                        .arg(c.kp.size())
                        .arg(n));
    const double periodMs = c.samplePeriod * 1000.0;
    const double wholeMs = std::round(periodMs);
    if (wholeMs < 1 || wholeMs > 255 || std::abs(periodMs - wholeMs) > 1e-9)
        throw Error(
            Text::tr("the sample period %1 ms cannot be sent to 0x60C2 (whole ms, 1 to 255)")
                .arg(periodMs));
    result->scaling = QVector<DriveScaling>(n);

    QList<SdoStep> steps;
    for (int j = 0; j < n; ++j) {
        const auto node = quint8(nodes[j]);
        SdoWriteSequence writes;
        writes << SdoWrite::make(node, objects::producerHeartbeatTime, 0, DataType::Unsigned16,
                                 effectiveHeartbeatPeriodMs(options))
               << SdoWrite::make(node, objects::modesOfOperation, 0, DataType::Integer8,
                                 objects::cyclicSynchronousPosition)
               << SdoWrite::make(node, objects::interpolationTimePeriod, 1, DataType::Unsigned8,
                                 wholeMs)
               << SdoWrite::make(node, objects::interpolationTimePeriod, 2, DataType::Integer8, -3)
               << SdoWrite::make(node, objects::gains, objects::gainKp, DataType::Real32, c.kp[j])
               << SdoWrite::make(node, objects::gains, objects::gainKi, DataType::Real32, c.ki[j])
               << SdoWrite::make(node, objects::gains, objects::gainKd, DataType::Real32, c.kd[j])
               << SdoWrite::make(node, objects::gains, objects::gainLambda, DataType::Real32,
                                 c.lambda)
               << SdoWrite::make(node, objects::torqueLimit, 0, DataType::Real32,
                                 plan.torqueLimit[j]);
        writes << pdoConfigurationWrites(node, PdoDirection::Receive, 1,
                                         objects::trialRpdoMapping());
        writes << pdoConfigurationWrites(node, PdoDirection::Transmit, 1,
                                         objects::trialTpdoMapping());
        for (const SdoWrite &w : writes)
            steps << SdoStep::write(w);

        const double periodUs = c.samplePeriod * 1e6;
        steps << SdoStep::read(
            node, objects::communicationCyclePeriod, 0, [node, periodUs](const QByteArray &d) {
                const double us = d.size() >= 4 ? double(canopen::readU32(d, 0)) : -1.0;
                if (std::abs(us - periodUs) > 0.5)
                    return Text::tr(
                               "node %1, object 0x1006:00: the robot's SYNC period is %2 us, the "
                               "plan needs %3 us")
                        .arg(node)
                        .arg(us)
                        .arg(periodUs);
                return QString();
            });
        DriveScaling *s = &result->scaling[j];
        steps << readPositive(node, motorRatedTorque, 0, &s->ratedTorque)
              << readPositive(node, positionEncoderResolution, 1, &s->increments)
              << readPositive(node, positionEncoderResolution, 2, &s->revolutions);
    }
    return steps;
}

} // namespace learnid
