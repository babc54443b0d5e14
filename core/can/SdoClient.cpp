#include "can/SdoClient.h"

#include "can/CanLink.h"
#include "can/CanLogging.h"
#include "can/CanOpen.h"
#include "can/SdoAbortCode.h"
#include "can/SdoProtocol.h"

#include <QTimer>
#include <optional>
#include <vector>

namespace learnid {

struct SdoClient::Transfer
{
    SdoResult result; ///< data holds the bytes to write (download) or read so far (upload)
    Callback done;
    bool initiated = false;   ///< the server accepted the initiate request
    bool toggle = false;      ///< toggle bit of the segment in flight
    int offset = 0;           ///< download: bytes already sent
    bool lastSent = false;    ///< download: the segment in flight is the last one
    qint64 expectedSize = -1; ///< upload: the size the server indicated
};

struct SdoClient::Channel
{
    quint8 node = 0;
    QQueue<Transfer> queue;
    std::optional<Transfer> active;
    QTimer timer;
    bool startScheduled = false;
};

SdoClient::SdoClient(CanLink *link, QObject *parent)
    : QObject(parent)
    , m_link(link)
{
    Q_ASSERT(link);
    connect(link, &CanLink::frameReceived, this, [this](const QCanBusFrame &frame) {
        const quint32 id = frame.frameId();
        if (frame.frameType() == QCanBusFrame::DataFrame && !frame.hasExtendedFrameFormat() &&
            id > canopen::sdoTxCobId(0) && id <= canopen::sdoTxCobId(canopen::maxNodeId))
            handleFrame(canopen::nodeOfCobId(id), sdo::normalised(frame.payload()));
    });
}

SdoClient::~SdoClient() = default;

quint64 SdoClient::upload(quint8 node, quint16 index, quint8 subIndex, Callback done)
{
    Transfer t;
    t.result.node = node;
    t.result.index = index;
    t.result.subIndex = subIndex;
    t.result.upload = true;
    t.done = std::move(done);
    return enqueue(std::move(t));
}

quint64 SdoClient::download(quint8 node, quint16 index, quint8 subIndex, const QByteArray &data,
                            Callback done)
{
    Transfer t;
    t.result.node = node;
    t.result.index = index;
    t.result.subIndex = subIndex;
    t.result.data = data;
    t.done = std::move(done);
    return enqueue(std::move(t));
}

int SdoClient::pendingTransfers(quint8 node) const
{
    const auto it = m_channels.find(node);
    if (it == m_channels.end())
        return 0;
    return int(it->second->queue.size()) + (it->second->active ? 1 : 0);
}

void SdoClient::cancelAll(const QString &reason)
{
    std::vector<std::pair<Callback, SdoResult>> ended;
    for (auto &[node, ch] : m_channels) {
        ch->timer.stop();
        if (ch->active) {
            const SdoResult &r = ch->active->result;
            m_link->send(sdo::makeFrame(canopen::sdoRxCobId(node),
                                        sdo::abort(r.index, r.subIndex, sdoabort::generalError)));
            ch->queue.prepend(std::move(*ch->active));
            ch->active.reset();
        }
        while (!ch->queue.isEmpty()) {
            Transfer t = ch->queue.dequeue();
            t.result.errorMessage = reason;
            if (t.result.upload)
                t.result.data.clear();
            ended.emplace_back(std::move(t.done), std::move(t.result));
        }
    }
    for (const auto &[done, result] : ended) {
        if (done)
            done(result);
        emit finished(result);
    }
}

quint64 SdoClient::enqueue(Transfer transfer)
{
    transfer.result.id = m_nextId++;
    const quint64 id = transfer.result.id;
    Channel &ch = channel(transfer.result.node);
    ch.queue.enqueue(std::move(transfer));
    if (!ch.startScheduled && !ch.active) {
        ch.startScheduled = true;
        const quint8 node = ch.node;
        QMetaObject::invokeMethod(
            this, [this, node] { startNext(node); }, Qt::QueuedConnection);
    }
    return id;
}

void SdoClient::startNext(quint8 node)
{
    Channel &ch = channel(node);
    ch.startScheduled = false;
    if (ch.active || ch.queue.isEmpty())
        return;
    ch.active = ch.queue.dequeue();
    const SdoResult &r = ch.active->result;
    if (!canopen::isValidNodeId(r.node))
        return fail(ch, 0, false, tr("%1 is not a valid CANopen node id (1 to 127).").arg(r.node));
    if (r.upload) {
        sendRequest(ch, sdo::initiate(quint8(sdo::ccsInitiateUpload << 5), r.index, r.subIndex));
        return;
    }
    const int size = int(r.data.size());
    if (size == 0)
        return fail(ch, 0, false, tr("There are no data to write."));
    if (size <= sdo::expeditedMaxSize) {
        const quint8 b0 = sdo::expeditedByte0(sdo::ccsInitiateDownload, size);
        sendRequest(ch, sdo::initiate(b0, r.index, r.subIndex, r.data));
        return;
    }
    QByteArray sizeBytes(4, '\0');
    canopen::writeU32(sizeBytes, 0, quint32(size));
    const quint8 b0 = quint8((sdo::ccsInitiateDownload << 5) | sdo::sizeIndicatedBit);
    sendRequest(ch, sdo::initiate(b0, r.index, r.subIndex, sizeBytes));
}

void SdoClient::handleFrame(quint8 node, const QByteArray &p)
{
    const auto it = m_channels.find(node);
    if (it == m_channels.end() || !it->second->active)
        return; // a late answer to a transfer that already ended
    Channel &ch = *it->second;
    ch.timer.stop();
    if (sdo::commandSpecifier(p) == sdo::csAbort)
        return fail(ch, sdo::abortCode(p), true, sdoabort::message(sdo::abortCode(p)));
    if (ch.active->result.upload)
        handleUpload(ch, p);
    else
        handleDownload(ch, p);
}

void SdoClient::handleDownload(Channel &ch, const QByteArray &p)
{
    Transfer &t = *ch.active;
    if (!t.initiated) {
        if (sdo::commandSpecifier(p) != sdo::scsInitiateDownload)
            return abortActive(ch, sdoabort::invalidCommandSpecifier);
        if (sdo::index(p) != t.result.index || sdo::subIndex(p) != t.result.subIndex)
            return abortActive(ch, sdoabort::generalError, tr("The answer names another object."));
        t.initiated = true;
        if (t.result.data.size() <= sdo::expeditedMaxSize)
            return succeed(ch);
        return sendNextSegment(ch);
    }
    if (sdo::commandSpecifier(p) != sdo::scsDownloadSegment)
        return abortActive(ch, sdoabort::invalidCommandSpecifier);
    if (sdo::toggle(p) != t.toggle)
        return abortActive(ch, sdoabort::toggleBitNotAlternated);
    if (t.lastSent)
        return succeed(ch);
    t.toggle = !t.toggle;
    sendNextSegment(ch);
}

void SdoClient::handleUpload(Channel &ch, const QByteArray &p)
{
    Transfer &t = *ch.active;
    if (!t.initiated) {
        if (sdo::commandSpecifier(p) != sdo::scsInitiateUpload)
            return abortActive(ch, sdoabort::invalidCommandSpecifier);
        if (sdo::index(p) != t.result.index || sdo::subIndex(p) != t.result.subIndex)
            return abortActive(ch, sdoabort::generalError, tr("The answer names another object."));
        t.initiated = true;
        const quint8 b0 = quint8(p.at(0));
        if (b0 & sdo::expeditedBit) {
            t.result.data = p.mid(4, sdo::expeditedSize(p));
            return succeed(ch);
        }
        t.expectedSize = (b0 & sdo::sizeIndicatedBit) ? qint64(canopen::readU32(p, 4)) : -1;
        t.toggle = false;
        return requestNextSegment(ch);
    }
    if (sdo::commandSpecifier(p) != sdo::scsUploadSegment)
        return abortActive(ch, sdoabort::invalidCommandSpecifier);
    if (sdo::toggle(p) != t.toggle)
        return abortActive(ch, sdoabort::toggleBitNotAlternated);
    t.result.data.append(p.mid(1, sdo::segmentSize(p)));
    const qint64 received = t.result.data.size();
    const bool last = sdo::isLastSegment(p);
    if (t.expectedSize >= 0 &&
        (received > t.expectedSize || (last && received != t.expectedSize))) {
        return abortActive(ch, sdoabort::lengthMismatch,
                           tr("The node announced %1 bytes but sent %2%3.")
                               .arg(t.expectedSize)
                               .arg(received)
                               .arg(last ? QString() : tr(" or more")));
    }
    if (last)
        return succeed(ch);
    t.toggle = !t.toggle;
    requestNextSegment(ch);
}

void SdoClient::sendNextSegment(Channel &ch)
{
    Transfer &t = *ch.active;
    const QByteArray chunk = t.result.data.mid(t.offset, sdo::segmentDataSize);
    t.offset += int(chunk.size());
    t.lastSent = t.offset >= t.result.data.size();
    const quint8 b0 =
        sdo::segmentByte0(sdo::ccsDownloadSegment, t.toggle, int(chunk.size()), t.lastSent);
    sendRequest(ch, sdo::segment(b0, chunk));
}

void SdoClient::requestNextSegment(Channel &ch)
{
    const bool toggle = ch.active->toggle;
    sendRequest(ch,
                sdo::segment(quint8((sdo::ccsUploadSegment << 5) | (toggle ? sdo::toggleBit : 0))));
}

bool SdoClient::sendRequest(Channel &ch, const QByteArray &payload)
{
    if (!m_link->send(sdo::makeFrame(canopen::sdoRxCobId(ch.node), payload))) {
        fail(ch, 0, false, m_link->lastError());
        return false;
    }
    ch.timer.start(m_timeout);
    return true;
}

void SdoClient::abortActive(Channel &ch, quint32 code, const QString &detail)
{
    const SdoResult &r = ch.active->result;
    m_link->send(
        sdo::makeFrame(canopen::sdoRxCobId(ch.node), sdo::abort(r.index, r.subIndex, code)));
    fail(ch, code, false, detail.isEmpty() ? sdoabort::message(code) : detail);
}

void SdoClient::succeed(Channel &ch)
{
    finish(ch, ch.active->result);
}

void SdoClient::fail(Channel &ch, quint32 code, bool byServer, const QString &reason)
{
    SdoResult r = ch.active->result;
    r.abortCode = code;
    r.abortedByServer = byServer;
    const QString object = canopen::objectAddress(r.index, r.subIndex);
    const QString what = r.upload ? tr("SDO read of %1 from node %2").arg(object).arg(r.node)
                                  : tr("SDO write of %1 to node %2").arg(object).arg(r.node);
    const QString code8 = code ? tr(" (abort code %1)").arg(sdoabort::codeText(code)) : QString();
    if (byServer)
        r.errorMessage = tr("The %1 was refused by the node%2: %3").arg(what, code8, reason);
    else if (code)
        r.errorMessage = tr("The %1 was aborted%2: %3").arg(what, code8, reason);
    else
        r.errorMessage = tr("The %1 failed: %2").arg(what, reason);
    if (r.upload)
        r.data.clear();
    qCDebug(lcCan) << r.errorMessage;
    finish(ch, std::move(r));
}

void SdoClient::finish(Channel &ch, SdoResult result)
{
    ch.timer.stop();
    Callback done = std::move(ch.active->done);
    ch.active.reset();
    if (!ch.queue.isEmpty() && !ch.startScheduled) {
        ch.startScheduled = true;
        const quint8 node = ch.node;
        QMetaObject::invokeMethod(
            this, [this, node] { startNext(node); }, Qt::QueuedConnection);
    }
    if (done)
        done(result);
    emit finished(result);
}

SdoClient::Channel &SdoClient::channel(quint8 node)
{
    auto &slot = m_channels[node];
    if (!slot) {
        slot = std::make_unique<Channel>();
        slot->node = node;
        slot->timer.setSingleShot(true);
        connect(&slot->timer, &QTimer::timeout, this, [this, node] {
            Channel &ch = channel(node);
            if (ch.active) {
                abortActive(ch, sdoabort::protocolTimeout,
                            tr("node %1 did not answer within %2 ms.").arg(node).arg(m_timeout));
            }
        });
    }
    return *slot;
}

} // namespace learnid
