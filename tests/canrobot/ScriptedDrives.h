#pragma once
// A small scripted robot side for the master's unit tests (not the robot simulator): one
// CANopen slave per node with the objects of docs/can-protocol.md, an ideal drive whose
// position follows the target exactly, a SYNC timer, and hooks to inject faults.

#include "can/CanLink.h"
#include "can/CanOpen.h"
#include "can/Cia402Drive.h"
#include "can/EmcyConsumer.h"
#include "can/HeartbeatProducer.h"
#include "can/JointIdentity.h"
#include "can/ManufacturerObjects.h"
#include "can/MemoryCanDevice.h"
#include "can/Nmt.h"
#include "can/ObjectDictionary.h"
#include "can/SdoAbortCode.h"
#include "can/SdoServer.h"

#include <QElapsedTimer>
#include <QTimer>
#include <cmath>
#include <functional>
#include <map>
#include <memory>

namespace learnid::test {

class ScriptedDrives : public QObject
{
public:
    struct Node
    {
        quint8 id = 0;
        int joint = 0; ///< 1-based, the node's place in the list
        ObjectDictionary od;
        std::unique_ptr<SdoServer> server;
        std::unique_ptr<HeartbeatProducer> heartbeat;
        Cia402Drive drive;
        NmtState nmt = NmtState::PreOperational;
        qint32 position = 0; ///< [inc]
        qint32 target = 0;
        qint16 torqueOffset = 0;
        bool fresh = false;
        quint16 pendingControlword = 0;
        bool hasControlword = false;
        int stores = 0;        ///< accepted writes of "save" to 0x1010:1
        bool answered = false; ///< an RPDO came in the last cycle (the master streams)
    };

    ScriptedDrives(QCanBusDevice *device, const QList<int> &nodes)
        : m_link(device)
    {
        for (const int id : nodes) {
            auto node = std::make_unique<Node>();
            node->id = quint8(id);
            node->joint = int(m_nodes.size()) + 1; // listed in joint order
            buildDictionary(*node);
            node->server = std::make_unique<SdoServer>(&m_link, node->id, &node->od);
            node->heartbeat = std::make_unique<HeartbeatProducer>(&m_link, node->id);
            node->drive.initialise();
            Node *n = node.get();
            connect(&n->od, &ObjectDictionary::valueWritten, this, [n](quint16 index, quint8) {
                if (index == objects::producerHeartbeatTime)
                    n->heartbeat->setPeriod(int(n->od.value(index, 0)));
            });
            m_nodes[node->id] = std::move(node);
        }
        connect(&m_link, &CanLink::frameReceived, this, &ScriptedDrives::onFrame);
        m_sync.setTimerType(Qt::PreciseTimer);
        m_sync.setSingleShot(true);
        connect(&m_sync, &QTimer::timeout, this, [this] {
            // Lock step, so that a loaded test machine cannot put the master's answer behind
            // the next SYNC: wait (up to 10 ms) for every operational node's RPDO.
            if (m_sinceSync.elapsed() < 8 && waitingForRpdo()) {
                m_sync.start(1);
                return;
            }
            sync();
            m_sinceSync.start();
            m_sync.start(m_period);
        });
    }

    /// Every drive stands at q [rad] (scaled as 0x608F says).
    void placeAt(const QList<double> &q)
    {
        int j = 0;
        for (auto &[nid, n] : m_nodes)
            n->position = qint32(std::lround(q.value(j++) * (1 << 20) / (2 * M_PI)));
    }
    Node &node(int id) { return *m_nodes.at(quint8(id)); }
    CanLink &link() { return m_link; }
    void startSync(int periodMs = 2)
    {
        m_period = periodMs;
        m_sinceSync.start();
        m_sync.start(periodMs);
    }
    void stopSync() { m_sync.stop(); }
    void setCounter(quint8 next) { m_counter = next; }
    qint64 syncs() const { return m_syncs; }
    /// Returns true to drop the TPDO of node at SYNC number n (1-based).
    std::function<bool(int node, qint64 n)> dropTpdo;
    /// Returns true to make node's set-point late at SYNC number n: the drive holds the one
    /// before and clears statusword bit 12 (only where the two differ, so that it shows).
    std::function<bool(int node, qint64 n)> lateSetpoint;
    /// Called at every SYNC in which a node is Operation enabled, after applying set-points.
    std::function<void(qint64 n)> onSync;
    QList<quint16> controlwords; ///< every controlword received in an RPDO, in order

    void sendEmcy(int id, quint16 code)
    {
        EmcyMessage m;
        m.node = quint8(id);
        m.errorCode = code;
        m.errorRegister = 0x81;
        m_link.send(encodeEmcy(m));
        node(id).drive.raiseFault();
        node(id).drive.completeFaultReaction();
    }

private:
    void buildDictionary(Node &n)
    {
        using canopen::DataType;
        using A = ObjectDictionary::Access;
        ObjectDictionary &od = n.od;
        od.add(0x1000, 0, DataType::Unsigned32, A::ReadOnly, 0x00020192);
        // Identity (docs/can-protocol.md §2.4): commissioned as joint n.joint of the paper arm.
        for (quint8 s = 1; s <= 4; ++s)
            od.add(0x1018, s, DataType::Unsigned32, A::ReadOnly, s == 4 ? 500 + n.joint : s);
        od.add(0x2400, 1, DataType::Unsigned32, A::ReadWrite,
               objects::robotIdentityOf(QStringLiteral("paper-2link")));
        od.add(0x2400, 2, DataType::Unsigned8, A::ReadWrite, n.joint);
        od.add(0x1006, 0, DataType::Unsigned32, A::ReadWrite, 2000);
        od.add(0x1010, 1, DataType::Unsigned32, A::ReadWrite, 0, [&n](const QByteArray &raw) {
            if (canopen::readU32(raw, 0) != objects::saveSignature)
                return sdoabort::cannotStore;
            ++n.stores;
            return quint32(0);
        });
        od.add(0x1017, 0, DataType::Unsigned16, A::ReadWrite, 0);
        od.add(0x6060, 0, DataType::Integer8, A::ReadWrite, 0,
               ObjectDictionary::rangeValidator(DataType::Integer8, 8, 8));
        od.add(0x60C2, 1, DataType::Unsigned8, A::ReadWrite, 2);
        od.add(0x60C2, 2, DataType::Integer8, A::ReadWrite, -3);
        for (quint8 s = 1; s <= 4; ++s)
            od.add(0x2100, s, DataType::Real32, A::ReadWrite, 0);
        od.add(0x2300, 0, DataType::Real32, A::ReadWrite, 1);
        od.add(0x2200, 0, DataType::Unsigned8, A::ReadWrite, 0);
        for (quint8 s = 1; s <= 3; ++s)
            od.add(0x2200, s, DataType::Real32, A::ReadWrite, 0);
        for (const quint16 comm : {0x1400, 0x1800}) {
            od.add(quint16(comm), 1, DataType::Unsigned32, A::ReadWrite, 0x80000000u);
            od.add(quint16(comm), 2, DataType::Unsigned8, A::ReadWrite, 1);
        }
        for (const quint16 map : {0x1600, 0x1A00}) {
            od.add(quint16(map), 0, DataType::Unsigned8, A::ReadWrite, 0);
            for (quint8 s = 1; s <= 3; ++s)
                od.add(quint16(map), s, DataType::Unsigned32, A::ReadWrite, 0);
        }
        od.add(0x6076, 0, DataType::Unsigned32, A::ReadOnly, 320); // 8 N m / 25
        od.add(0x608F, 1, DataType::Unsigned32, A::ReadOnly, 1u << 20);
        od.add(0x608F, 2, DataType::Unsigned32, A::ReadOnly, 1);
    }

    bool waitingForRpdo() const
    {
        for (const auto &[nid, n] : m_nodes)
            if (n->nmt == NmtState::Operational && n->answered && !n->fresh)
                return true;
        return false;
    }

    void onFrame(const QCanBusFrame &frame)
    {
        const quint32 id = frame.frameId();
        if (id == 0) {
            for (auto &[nid, n] : m_nodes) {
                if (const auto command = nmtCommandFor(frame, nid)) {
                    n->nmt = nmtStateAfter(*command, n->nmt);
                    n->heartbeat->setState(n->nmt);
                }
            }
            return;
        }
        if (id > 0x200 && id < 0x280 && frame.payload().size() >= 8) {
            const auto it = m_nodes.find(quint8(id - 0x200));
            if (it == m_nodes.end() || it->second->nmt != NmtState::Operational)
                return;
            Node &n = *it->second;
            const QByteArray p = frame.payload();
            n.target = qint32(canopen::readU32(p, 0));
            n.torqueOffset = qint16(canopen::readU16(p, 4));
            n.pendingControlword = canopen::readU16(p, 6);
            n.hasControlword = true;
            n.fresh = true;
            controlwords.append(n.pendingControlword);
        }
    }

    void sync()
    {
        ++m_syncs;
        m_link.send(QCanBusFrame(canopen::syncCobId, QByteArray(1, char(m_counter))));
        m_counter = quint8(m_counter % 240 + 1);
        for (auto &[nid, n] : m_nodes) {
            if (n->nmt != NmtState::Operational)
                continue;
            if (n->hasControlword) {
                n->drive.applyControlword(n->pendingControlword);
                n->hasControlword = false;
            }
            const bool enabled = n->drive.state() == cia402::State::OperationEnabled;
            const bool late = enabled && n->fresh && n->target != n->position && lateSetpoint &&
                              lateSetpoint(nid, m_syncs);
            const bool followed = enabled && n->fresh && !late;
            if (followed)
                n->position = n->target; // an ideal drive
            quint16 sw = n->drive.statusword();
            if (followed)
                sw |= 0x1000;
            n->answered = n->fresh;
            n->fresh = false;
            if (dropTpdo && dropTpdo(nid, m_syncs))
                continue;
            QByteArray p(8, '\0');
            canopen::writeU32(p, 0, quint32(n->position));
            canopen::writeU16(p, 4, quint16(n->torqueOffset));
            canopen::writeU16(p, 6, sw);
            m_link.send(QCanBusFrame(canopen::tpdoCobId(1, nid), p));
        }
        if (onSync)
            onSync(m_syncs);
    }

    CanLink m_link;
    std::map<quint8, std::unique_ptr<Node>> m_nodes;
    QTimer m_sync;
    QElapsedTimer m_sinceSync;
    int m_period = 2;
    quint8 m_counter = 1;
    qint64 m_syncs = 0;
};

} // namespace learnid::test
