#include "can/SdoServer.h"

#include "can/CanLink.h"
#include "can/CanLogging.h"
#include "can/CanOpen.h"
#include "can/ObjectDictionary.h"
#include "can/SdoAbortCode.h"
#include "can/SdoProtocol.h"

namespace learnid {

SdoServer::SdoServer(CanLink *link, quint8 node, ObjectDictionary *dictionary, QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_node(node)
    , m_dictionary(dictionary)
{
    Q_ASSERT(link && dictionary && canopen::isValidNodeId(node));
    m_timer.setSingleShot(true);
    m_timer.setInterval(1000);
    connect(&m_timer, &QTimer::timeout, this,
            [this] { sendAbort(m_index, m_subIndex, sdoabort::protocolTimeout); });
    connect(link, &CanLink::frameReceived, this, [this](const QCanBusFrame &frame) {
        if (frame.frameType() == QCanBusFrame::DataFrame && !frame.hasExtendedFrameFormat() &&
            frame.frameId() == canopen::sdoRxCobId(m_node) && !m_silent)
            handleFrame(sdo::normalised(frame.payload()));
    });
}

void SdoServer::handleFrame(const QByteArray &p)
{
    switch (sdo::commandSpecifier(p)) {
    case sdo::ccsInitiateDownload:
        initiateDownload(p);
        break;
    case sdo::ccsDownloadSegment:
        downloadSegment(p);
        break;
    case sdo::ccsInitiateUpload:
        initiateUpload(p);
        break;
    case sdo::ccsUploadSegment:
        uploadSegment(p);
        break;
    case sdo::csAbort:
        if (m_phase != Phase::Idle)
            emit transferAborted(m_index, m_subIndex, sdo::abortCode(p), true);
        reset();
        break;
    default: // block transfers and reserved specifiers
        sendAbort(sdo::index(p), sdo::subIndex(p), sdoabort::invalidCommandSpecifier);
        break;
    }
}

void SdoServer::initiateDownload(const QByteArray &p)
{
    reset(); // a new initiate ends any transfer in progress
    const quint16 index = sdo::index(p);
    const quint8 sub = sdo::subIndex(p);
    const quint8 b0 = quint8(p.at(0));
    const bool expedited = b0 & sdo::expeditedBit;
    const bool sized = b0 & sdo::sizeIndicatedBit;
    if (const quint32 code = refusal(index, sub, true))
        return sendAbort(index, sub, code);
    if (expedited) {
        QByteArray data = p.mid(4, sdo::expeditedSize(p));
        // Without a size, a fixed-size object takes as many of the 4 bytes as it needs.
        if (!sized && m_dictionary->contains(index, sub)) {
            const int fixed = canopen::dataTypeSize(m_dictionary->type(index, sub));
            if (fixed > 0)
                data.truncate(fixed);
        }
        if (const quint32 code = m_dictionary->write(index, sub, data))
            return sendAbort(index, sub, code);
        return respond(sdo::initiate(quint8(sdo::scsInitiateDownload << 5), index, sub));
    }
    const qint64 size = sized ? qint64(canopen::readU32(p, 4)) : -1;
    if (const quint32 code = m_dictionary->checkWrite(index, sub, size))
        return sendAbort(index, sub, code);
    m_phase = Phase::Downloading;
    m_index = index;
    m_subIndex = sub;
    m_expectedSize = size;
    m_toggle = false;
    respond(sdo::initiate(quint8(sdo::scsInitiateDownload << 5), index, sub));
    m_timer.start();
}

void SdoServer::downloadSegment(const QByteArray &p)
{
    if (m_phase != Phase::Downloading)
        return sendAbort(m_index, m_subIndex, sdoabort::invalidCommandSpecifier);
    if (sdo::toggle(p) != m_toggle)
        return sendAbort(m_index, m_subIndex, sdoabort::toggleBitNotAlternated);
    m_buffer.append(p.mid(1, sdo::segmentSize(p)));
    if (m_expectedSize >= 0 && m_buffer.size() > m_expectedSize)
        return sendAbort(m_index, m_subIndex, sdoabort::lengthTooHigh);
    const bool toggle = m_toggle;
    if (sdo::isLastSegment(p))
        return finishDownload();
    m_toggle = !m_toggle;
    respond(sdo::segment(quint8((sdo::scsDownloadSegment << 5) | (toggle ? sdo::toggleBit : 0))));
    m_timer.start();
}

void SdoServer::finishDownload()
{
    const quint16 index = m_index;
    const quint8 sub = m_subIndex;
    const bool toggle = m_toggle;
    if (m_expectedSize >= 0 && m_buffer.size() != m_expectedSize)
        return sendAbort(index, sub, sdoabort::lengthMismatch);
    const QByteArray data = m_buffer;
    reset();
    if (const quint32 code = m_dictionary->write(index, sub, data))
        return sendAbort(index, sub, code);
    respond(sdo::segment(quint8((sdo::scsDownloadSegment << 5) | (toggle ? sdo::toggleBit : 0))));
}

void SdoServer::initiateUpload(const QByteArray &p)
{
    reset();
    const quint16 index = sdo::index(p);
    const quint8 sub = sdo::subIndex(p);
    if (const quint32 code = refusal(index, sub, false))
        return sendAbort(index, sub, code);
    QByteArray data;
    if (const quint32 code = m_dictionary->read(index, sub, &data))
        return sendAbort(index, sub, code);
    if (!data.isEmpty() && data.size() <= sdo::expeditedMaxSize) {
        const quint8 b0 = sdo::expeditedByte0(sdo::scsInitiateUpload, int(data.size()));
        return respond(sdo::initiate(b0, index, sub, data));
    }
    QByteArray size(4, '\0');
    canopen::writeU32(size, 0, quint32(data.size()));
    m_phase = Phase::Uploading;
    m_index = index;
    m_subIndex = sub;
    m_buffer = data;
    m_offset = 0;
    m_toggle = false;
    respond(sdo::initiate(quint8((sdo::scsInitiateUpload << 5) | sdo::sizeIndicatedBit), index, sub,
                          size));
    m_timer.start();
}

void SdoServer::uploadSegment(const QByteArray &p)
{
    if (m_phase != Phase::Uploading)
        return sendAbort(m_index, m_subIndex, sdoabort::invalidCommandSpecifier);
    if (sdo::toggle(p) != m_toggle)
        return sendAbort(m_index, m_subIndex, sdoabort::toggleBitNotAlternated);
    const QByteArray chunk = m_buffer.mid(m_offset, sdo::segmentDataSize);
    m_offset += int(chunk.size());
    const bool last = m_offset >= m_buffer.size();
    const quint8 b0 = sdo::segmentByte0(sdo::scsUploadSegment, m_toggle, int(chunk.size()), last);
    m_toggle = !m_toggle;
    if (last)
        reset();
    else
        m_timer.start();
    respond(sdo::segment(b0, chunk));
}

void SdoServer::sendAbort(quint16 index, quint8 subIndex, quint32 code)
{
    qCDebug(lcCan) << "SDO server" << m_node << "aborts" << canopen::objectAddress(index, subIndex)
                   << sdoabort::codeText(code);
    reset();
    respond(sdo::abort(index, subIndex, code));
    emit transferAborted(index, subIndex, code, false);
}

void SdoServer::respond(const QByteArray &payload)
{
    m_link->send(sdo::makeFrame(canopen::sdoTxCobId(m_node), payload));
}

void SdoServer::reset()
{
    m_timer.stop();
    m_phase = Phase::Idle;
    m_buffer.clear();
    m_expectedSize = -1;
    m_offset = 0;
    m_toggle = false;
}

quint32 SdoServer::refusal(quint16 index, quint8 subIndex, bool write) const
{
    return m_refusal ? m_refusal(index, subIndex, write) : 0;
}

} // namespace learnid
