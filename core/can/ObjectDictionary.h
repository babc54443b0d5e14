#pragma once

#include "can/CanOpen.h"

#include <QByteArray>
#include <QObject>
#include <functional>
#include <map>

namespace learnid {

/// The object dictionary of a CANopen slave (the simulator's drives, and tests): entries keyed
/// by (index, sub-index), each with a data type, access rights, its raw little-endian value and
/// an optional write validator. SDO access goes through read()/write(), which answer with a
/// CiA 301 abort code (0 on success); the slave's own application uses value()/setValue().
class ObjectDictionary : public QObject
{
    Q_OBJECT

public:
    enum class Access { ReadOnly, WriteOnly, ReadWrite, Constant };
    /// Checks raw bytes about to be written (of the right length already); returns 0 to accept
    /// or the abort code to answer, e.g. sdoabort::valueTooHigh.
    using Validator = std::function<quint32(const QByteArray &raw)>;

    explicit ObjectDictionary(QObject *parent = nullptr);

    /// Adds a numeric entry. Throws learnid::Error when the entry exists, the type is not
    /// numeric or the initial value does not fit it.
    void add(quint16 index, quint8 subIndex, canopen::DataType type, Access access,
             double initial = 0.0, Validator validator = {});
    /// Adds a variable-length entry (VISIBLE_STRING, OCTET_STRING, DOMAIN); maxSize bounds
    /// what may be written (0: unbounded).
    void addBytes(quint16 index, quint8 subIndex, canopen::DataType type, Access access,
                  const QByteArray &initial, int maxSize = 0, Validator validator = {});

    bool contains(quint16 index, quint8 subIndex) const;
    bool containsIndex(quint16 index) const;
    canopen::DataType type(quint16 index, quint8 subIndex) const;

    /// SDO read: the bytes, or the abort code (object or sub-index missing, write-only).
    quint32 read(quint16 index, quint8 subIndex, QByteArray *out) const;
    /// Whether an SDO write of size bytes could succeed, before the data arrive (segmented
    /// download); size < 0 when not indicated. Returns 0 or the abort code.
    quint32 checkWrite(quint16 index, quint8 subIndex, qint64 size) const;
    /// SDO write: checks existence, access, length and the validator; emits valueWritten().
    quint32 write(quint16 index, quint8 subIndex, const QByteArray &data);

    /// Local access by the slave's application, bypassing access rights. Throw learnid::Error
    /// for a missing entry or a value that does not fit.
    double value(quint16 index, quint8 subIndex) const;
    void setValue(quint16 index, quint8 subIndex, double value);
    QByteArray bytes(quint16 index, quint8 subIndex) const;
    void setBytes(quint16 index, quint8 subIndex, const QByteArray &bytes);

    /// A validator accepting numeric values in [min, max] (valueTooLow / valueTooHigh otherwise).
    static Validator rangeValidator(canopen::DataType type, double min, double max);

signals:
    /// After a successful SDO write (not after setValue/setBytes).
    void valueWritten(quint16 index, quint8 subIndex);

private:
    struct Entry
    {
        canopen::DataType type;
        Access access;
        QByteArray value;
        int maxSize = 0;
        Validator validator;
    };
    static quint32 key(quint16 index, quint8 subIndex) { return (quint32(index) << 8) | subIndex; }
    const Entry *find(quint16 index, quint8 subIndex) const;
    const Entry &entry(quint16 index, quint8 subIndex) const;
    /// objectDoesNotExist or subIndexDoesNotExist for a missing entry.
    quint32 missingCode(quint16 index) const;
    void insert(quint16 index, quint8 subIndex, Entry entry);

    std::map<quint32, Entry> m_entries;
};

} // namespace learnid
