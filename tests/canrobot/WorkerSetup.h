#pragma once
// A CanRobotWorker on a memory bus with ScriptedDrives 1 and 2 as the robot side, run by an
// event loop of its own: the rig of tst_canrobot_canrobotworker and tst_canrobot_timeouts.

#include "ScriptedDrives.h"
#include "TestPlan.h"
#include "can/MemoryCanBus.h"
#include "canrobot/CanRobotWorker.h"

#include <QEventLoop>
#include <QPointer>
#include <QTimer>
#include <optional>

namespace learnid::test {

struct WorkerSetup
{
    MemoryCanBus bus;
    MemoryCanDevice *robotDevice = bus.createDevice(QStringLiteral("robot"));
    test::ScriptedDrives drives{robotDevice, {1, 2}};
    CanRobotOptions options;
    std::unique_ptr<CanRobotWorker> worker;
    QPointer<MemoryCanDevice> master; ///< the master's device, once connected
    QString refuseDevice; ///< when set, the factory makes no device and answers this error

    explicit WorkerSetup(CanRobotOptions o = {})
        : options(std::move(o))
    {
        robotDevice->connectDevice();
        drives.placeAt({0.3, 1.2}); // at the plan's start: the shortest return move (0.5 s)
        options.plugin = QStringLiteral("memory");
        options.interface = QStringLiteral("master");
        MemoryCanBus *b = &bus;
        worker = std::make_unique<CanRobotWorker>(
            test::testModel(), options, [this, b](QString *error) -> QCanBusDevice * {
                if (!refuseDevice.isEmpty()) {
                    *error = refuseDevice;
                    return nullptr;
                }
                master = new MemoryCanDevice(QStringLiteral("master"), b);
                return master.data();
            });
    }

    TrialRecord run(const TrialPlan &plan, const TrialMonitor &monitor = {})
    {
        // A real event loop: QTest::qWaitFor sleeps between its rounds, which would delay the
        // master's answers behind the next SYNC.
        std::optional<TrialRecord> result;
        QEventLoop loop;
        worker->runTrial(plan, monitor, [&](const TrialRecord &r) {
            result = r;
            loop.quit();
        });
        QTimer::singleShot(20000, &loop, &QEventLoop::quit);
        loop.exec();
        return result.value_or(TrialRecord{});
    }

    QString apply(const Eigen::VectorXd &phi)
    {
        std::optional<QString> result;
        QEventLoop loop;
        worker->apply(phi, [&](const QString &e) {
            result = e;
            loop.quit();
        });
        QTimer::singleShot(10000, &loop, &QEventLoop::quit);
        loop.exec();
        return result.value_or(QStringLiteral("timeout"));
    }
};

} // namespace learnid::test
