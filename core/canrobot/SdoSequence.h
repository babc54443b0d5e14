#pragma once

#include "can/SdoWrite.h"

#include <QByteArray>
#include <QList>
#include <QObject>
#include <QPointer>
#include <functional>

namespace learnid {

class SdoClient;

/// One SDO access of a sequence: a write of raw bytes, or a read whose bytes go to onRead
/// (which may refuse them with a message, e.g. a read-back that differs).
struct SdoStep
{
    quint8 node = 0;
    quint16 index = 0;
    quint8 subIndex = 0;
    bool upload = false;
    QByteArray data; ///< download: the bytes to write
    std::function<QString(const QByteArray &data)> onRead;

    static SdoStep write(const SdoWrite &w);
    static SdoStep read(quint8 node, quint16 index, quint8 subIndex,
                        std::function<QString(const QByteArray &)> onRead);
};

/// Runs SDO accesses one after the other and stops at the first failure, so that nothing after
/// a refused write is sent (apply stores nothing when a write failed).
class SdoSequence : public QObject
{
    Q_OBJECT

public:
    /// done(error): empty when every step succeeded, else the client's words (node, object,
    /// abort code and its meaning) or onRead's.
    using Done = std::function<void(const QString &error)>;

    SdoSequence(SdoClient *client, QObject *parent = nullptr);

    /// Starts the steps; done is called exactly once, never from inside run().
    void run(QList<SdoStep> steps, Done done);
    bool isRunning() const { return bool(m_done); }
    /// Ends a running sequence with reason (the transfer in flight is aborted on the bus).
    void cancel(const QString &reason);
    int stepsDone() const { return m_next; }

private:
    void startNext();
    void finish(const QString &error);

    SdoClient *m_client;
    QList<SdoStep> m_steps;
    int m_next = 0;
    quint64 m_generation = 0;
    Done m_done;
};

} // namespace learnid
