#pragma once

#include <QByteArray>
#include <QMetaType>
#include <QObject>
#include <QQueue>
#include <QString>
#include <functional>
#include <map>
#include <memory>

class QTimer;

namespace learnid {

class CanLink;

/// How one SDO transfer ended.
struct SdoResult
{
    quint64 id = 0; ///< as returned by SdoClient::upload()/download()
    quint8 node = 0;
    quint16 index = 0;
    quint8 subIndex = 0;
    bool upload = false;
    QByteArray data;       ///< the bytes read (upload) or written (download)
    quint32 abortCode = 0; ///< the CiA 301 code of an aborted transfer, 0 otherwise
    bool abortedByServer = false;
    QString errorMessage; ///< empty on success; otherwise what failed, for the technician

    bool ok() const { return errorMessage.isEmpty(); }
};

/// The SDO client of the master (CiA 301 §7.2.4): expedited and segmented uploads and
/// downloads, asynchronous, one transfer at a time per node, further transfers to that node
/// queued in call order (transfers to different nodes run concurrently).
///
/// Every request must be answered within timeout() or the client aborts the transfer with
/// protocolTimeout. A result is never delivered from inside upload()/download().
class SdoClient : public QObject
{
    Q_OBJECT

public:
    using Callback = std::function<void(const SdoResult &result)>;

    explicit SdoClient(CanLink *link, QObject *parent = nullptr);
    ~SdoClient() override;

    /// The time the server has to answer each request [ms] (default 500).
    void setTimeout(int ms) { m_timeout = ms; }
    int timeout() const { return m_timeout; }

    /// Reads node's object; done (if set) is called just before finished() is emitted.
    /// Returns the transfer id.
    quint64 upload(quint8 node, quint16 index, quint8 subIndex, Callback done = {});
    /// Writes data (at least 1 byte; up to 4 expedited, more segmented) to node's object.
    quint64 download(quint8 node, quint16 index, quint8 subIndex, const QByteArray &data,
                     Callback done = {});

    /// Transfers not finished yet for node (active and queued).
    int pendingTransfers(quint8 node) const;
    /// Ends every transfer: active ones are aborted on the bus (generalError), all of them
    /// finish with the given reason.
    void cancelAll(const QString &reason);

signals:
    void finished(const learnid::SdoResult &result);

private:
    struct Transfer;
    struct Channel;

    quint64 enqueue(Transfer transfer);
    void startNext(quint8 node);
    void handleFrame(quint8 node, const QByteArray &payload);
    void handleDownload(Channel &channel, const QByteArray &p);
    void handleUpload(Channel &channel, const QByteArray &p);
    void sendNextSegment(Channel &channel);
    void requestNextSegment(Channel &channel);
    bool sendRequest(Channel &channel, const QByteArray &payload);
    void abortActive(Channel &channel, quint32 code, const QString &detail = {});
    void succeed(Channel &channel);
    void fail(Channel &channel, quint32 code, bool byServer, const QString &reason);
    void finish(Channel &channel, SdoResult result);
    Channel &channel(quint8 node);

    CanLink *m_link;
    int m_timeout = 500;
    quint64 m_nextId = 1;
    std::map<quint8, std::unique_ptr<Channel>> m_channels;
};

} // namespace learnid

Q_DECLARE_METATYPE(learnid::SdoResult)
