#include "canrobot/SdoSequence.h"

#include "can/SdoClient.h"

#include <utility>

namespace learnid {

SdoStep SdoStep::write(const SdoWrite &w)
{
    SdoStep s;
    s.node = w.node;
    s.index = w.index;
    s.subIndex = w.subIndex;
    s.data = w.raw;
    return s;
}

SdoStep SdoStep::read(quint8 node, quint16 index, quint8 subIndex,
                      std::function<QString(const QByteArray &)> onRead)
{
    SdoStep s;
    s.node = node;
    s.index = index;
    s.subIndex = subIndex;
    s.upload = true;
    s.onRead = std::move(onRead);
    return s;
}

SdoSequence::SdoSequence(SdoClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    Q_ASSERT(client);
}

void SdoSequence::run(QList<SdoStep> steps, Done done)
{
    m_steps = std::move(steps);
    m_next = 0;
    m_done = std::move(done);
    const quint64 generation = ++m_generation;
    QMetaObject::invokeMethod(
        this,
        [this, generation] {
            if (generation == m_generation)
                startNext();
        },
        Qt::QueuedConnection);
}

void SdoSequence::cancel(const QString &reason)
{
    if (!m_done)
        return;
    ++m_generation; // results of the transfer in flight are ignored from now on
    m_client->cancelAll(reason);
    finish(reason);
}

void SdoSequence::startNext()
{
    if (m_next >= m_steps.size())
        return finish({});
    const SdoStep &step = m_steps.at(m_next);
    const quint64 generation = m_generation;
    auto done = [this, generation](const SdoResult &result) {
        if (generation != m_generation)
            return;
        if (!result.ok())
            return finish(result.errorMessage);
        const SdoStep &s = m_steps.at(m_next);
        if (s.upload && s.onRead) {
            const QString error = s.onRead(result.data);
            if (!error.isEmpty())
                return finish(error);
        }
        ++m_next;
        startNext();
    };
    if (step.upload)
        m_client->upload(step.node, step.index, step.subIndex, done);
    else
        m_client->download(step.node, step.index, step.subIndex, step.data, done);
}

void SdoSequence::finish(const QString &error)
{
    Done done = std::exchange(m_done, nullptr);
    ++m_generation;
    if (done)
        done(error);
}

} // namespace learnid
