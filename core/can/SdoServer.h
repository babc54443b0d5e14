#pragma once

#include <QByteArray>
#include <QObject>
#include <QTimer>
#include <functional>

namespace learnid {

class CanLink;
class ObjectDictionary;

/// The SDO server of one CANopen slave (CiA 301 §7.2.4): answers expedited and segmented
/// uploads and downloads on 0x600 + node / 0x580 + node from its object dictionary, and aborts
/// with the code the dictionary gives, or toggleBitNotAlternated, invalidCommandSpecifier
/// (block transfers are not supported), lengthMismatch, protocolTimeout.
class SdoServer : public QObject
{
    Q_OBJECT

public:
    /// Fault injection: returns an abort code to refuse the access, 0 to serve it.
    using Refusal = std::function<quint32(quint16 index, quint8 subIndex, bool write)>;

    SdoServer(CanLink *link, quint8 node, ObjectDictionary *dictionary, QObject *parent = nullptr);

    quint8 node() const { return m_node; }
    /// How long the server waits for the client's next segment before aborting [ms].
    void setSegmentTimeout(int ms) { m_timer.setInterval(ms); }
    int segmentTimeout() const { return m_timer.interval(); }

    void setRefusal(Refusal refusal) { m_refusal = std::move(refusal); }
    /// Fault injection: a silent server ignores every request (as a node that stopped answering).
    void setSilent(bool silent) { m_silent = silent; }
    bool isSilent() const { return m_silent; }

signals:
    /// A transfer ended with an abort, sent by this server (byClient false) or the client.
    void transferAborted(quint16 index, quint8 subIndex, quint32 code, bool byClient);

private:
    enum class Phase { Idle, Downloading, Uploading };

    void handleFrame(const QByteArray &payload);
    void initiateDownload(const QByteArray &p);
    void downloadSegment(const QByteArray &p);
    void initiateUpload(const QByteArray &p);
    void uploadSegment(const QByteArray &p);
    void finishDownload();
    void sendAbort(quint16 index, quint8 subIndex, quint32 code);
    void respond(const QByteArray &payload);
    void reset();
    quint32 refusal(quint16 index, quint8 subIndex, bool write) const;

    CanLink *m_link;
    quint8 m_node;
    ObjectDictionary *m_dictionary;
    Refusal m_refusal;
    bool m_silent = false;

    Phase m_phase = Phase::Idle;
    quint16 m_index = 0;
    quint8 m_subIndex = 0;
    QByteArray m_buffer;
    qint64 m_expectedSize = -1; ///< segmented download: the indicated size, -1 if none
    int m_offset = 0;           ///< segmented upload: bytes already sent
    bool m_toggle = false;      ///< the toggle bit the next segment must carry
    QTimer m_timer;
};

} // namespace learnid
