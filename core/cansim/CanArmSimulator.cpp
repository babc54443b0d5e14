#include "cansim/CanArmSimulator.h"

#include "can/CanLink.h"
#include "can/SdoAbortCode.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QSet>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CanArmSimulator)
};

void checkSettings(const CanArmSettings &s)
{
    if (!s.model)
        throw Error(Text::tr("The simulated arm has no robot model."));
    const int n = s.model->dof();
    if (s.nodes.size() != n) {
        throw Error(
            Text::tr("--nodes: the %1 arm has %2 joints, so %2 node ids are needed, not %3.")
                .arg(s.model->id())
                .arg(n)
                .arg(s.nodes.size()));
    }
    QSet<int> seen;
    for (const int id : s.nodes) {
        if (!canopen::isValidNodeId(id))
            throw Error(Text::tr("--nodes: %1 is not a CANopen node id (1 to 127).").arg(id));
        if (seen.contains(id))
            throw Error(Text::tr("--nodes: node %1 is listed twice.").arg(id));
        seen.insert(id);
    }
    if (s.trueParameters.size() != s.model->parameterCount() || s.torqueLimits.size() != n ||
        s.initialPose.size() != n || s.controller.dof() != n) {
        throw Error(
            Text::tr("The simulated arm's parameters, torque limits, initial pose or gains do "
                     "not fit the %1 model.")
                .arg(s.model->id()));
    }
    if (!(s.controller.samplePeriod >= 1e-3 && s.controller.samplePeriod <= 0.1))
        throw Error(Text::tr("The SYNC period must be 1 to 100 ms, not %1 s.")
                        .arg(s.controller.samplePeriod));
}

} // namespace

CanArmSimulator::CanArmSimulator(CanLink *link, const CanArmSettings &settings,
                                 const CanSimFaults &faults, QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_faults(faults)
{
    checkSettings(settings);
    const int n = settings.model->dof();
    m_syncPeriodUs = quint32(std::lround(settings.controller.samplePeriod * 1e6));
    MeasurementOptions measurement = settings.measurement;
    if (measurement.encoderCounts <= 0)
        measurement.encoderCounts = cansim::idealIncrements;
    m_arm = std::make_unique<ArmSimulation<>>(settings.model, settings.trueParameters, measurement,
                                              settings.controller.samplePeriod);
    m_arm->reset(settings.initialPose);
    m_withPayload = settings.trueParameters;
    if (settings.bareParameters.size() == settings.trueParameters.size())
        m_bare = settings.bareParameters;
    std::seed_seq seq{quint64(measurement.seed), quint64(0xC4A5)};
    m_dropRng.seed(seq);

    for (int j = 0; j < n; ++j) {
        DriveNodeSettings d;
        d.node = quint8(settings.nodes[j]);
        d.joint = j + 1;
        d.kp = settings.controller.kp[j];
        d.ki = settings.controller.ki[j];
        d.kd = settings.controller.kd[j];
        d.lambda = settings.controller.lambda;
        d.torqueLimit = settings.torqueLimits[j];
        d.increments = measurement.encoderCounts;
        d.parameterCount = settings.model->parameterCount();
        d.syncPeriodUs = m_syncPeriodUs;
        d.setPointTimeoutSyncs = settings.setPointTimeoutSyncs;
        d.identity = cansim::driveIdentityOfJoint(j + 1);
        d.robotIdentity = settings.robotIdentity;
        d.commissionedJoint = settings.robotIdentity != 0 ? j + 1 : 0;
        auto *node = new DriveNode(link, d, this);
        connect(node, &DriveNode::parametersStored, this, &CanArmSimulator::parametersStored);
        if (faults.refusedWrite) {
            const auto [index, sub] = *faults.refusedWrite;
            node->sdoServer().setRefusal(
                [index = index, sub = sub](quint16 i, quint8 s, bool write) {
                    return write && i == index && s == sub ? sdoabort::cannotStore : 0u;
                });
        }
        m_nodes.append(node);
    }
    if (faults.emcyAtSample >= 1)
        m_nodes.first()->setFaultAtEnabledSync(faults.emcyAtSample, cansim::emcyFollowingError);
    m_qMeasured.resize(n);
    m_tau.resize(n);
    m_tauMeasured.resize(n);
    m_limits.resize(n);
    connect(&m_sync, &SyncProducer::due, this, [this] {
        // Frames that reached this process before the SYNC is due belong to this period: when
        // the process was descheduled, the timer and the sockets become ready together and
        // the timer may be served first. The sockets (virtualcan relays through its server,
        // which may live in this process: two hops) are served before the SYNC goes out.
        for (int hop = 0; hop < 2; ++hop)
            QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
        syncCycle();
    });
    connect(link, &CanLink::frameSent, this, &CanArmSimulator::countSentFrame);
    if (faults.silentAfterFrames == 0)
        silence();
}

void CanArmSimulator::bootUp()
{
    for (DriveNode *node : std::as_const(m_nodes))
        node->bootUp();
}

void CanArmSimulator::start()
{
    bootUp();
    m_sync.start(m_syncPeriodUs);
}

void CanArmSimulator::stop()
{
    m_sync.stop();
}

void CanArmSimulator::syncCycle()
{
    if (m_silent)
        return;
    const int n = dof();
    m_arm->measureAngles(m_qMeasured);
    for (int j = 0; j < n; ++j) {
        const DriveSyncOutput out = m_nodes[j]->sync(m_qMeasured[j]);
        m_tau[j] = out.torque;
        m_arm->setBraked(j, !out.powered);
        m_limits[j] = m_nodes[j]->torqueLimit();
    }
    m_link->send(SyncProducer::frame(m_sync.advance()));
    ++m_syncCount;
    m_arm->measureTorques(m_tau, m_tauMeasured);
    m_arm->addTorqueNoise(m_tauMeasured, m_limits);
    for (int j = 0; j < n; ++j) {
        const bool drop =
            m_faults.dropFraction > 0.0 && m_uniform(m_dropRng) < m_faults.dropFraction;
        m_nodes[j]->sendAfterSync(m_tauMeasured[j], drop);
    }
    m_arm->integrate(m_tau);
}

void CanArmSimulator::countSentFrame()
{
    ++m_framesSent;
    if (m_faults.silentAfterFrames >= 0 && m_framesSent >= m_faults.silentAfterFrames && !m_silent)
        silence();
}

void CanArmSimulator::silence()
{
    m_silent = true;
    m_sync.stop();
    for (DriveNode *node : std::as_const(m_nodes))
        node->setSilent(true);
    emit silenced();
}

bool CanArmSimulator::setPayloadMounted(bool mounted)
{
    if (!hasPayload())
        return false;
    m_arm->setTrueParameters(mounted ? m_withPayload : m_bare);
    return true;
}

} // namespace learnid
