#include "can/ObjectDictionary.h"

#include "can/SdoAbortCode.h"
#include "model/Error.h"

namespace learnid {

using canopen::DataType;

ObjectDictionary::ObjectDictionary(QObject *parent)
    : QObject(parent)
{}

void ObjectDictionary::add(quint16 index, quint8 subIndex, DataType type, Access access,
                           double initial, Validator validator)
{
    if (!canopen::isNumeric(type)) {
        throw Error(tr("Object %1: %2 is not numeric; use addBytes().")
                        .arg(canopen::objectAddress(index, subIndex), canopen::dataTypeName(type)));
    }
    insert(index, subIndex,
           Entry{type, access, canopen::encodeValue(type, initial), 0, std::move(validator)});
}

void ObjectDictionary::addBytes(quint16 index, quint8 subIndex, DataType type, Access access,
                                const QByteArray &initial, int maxSize, Validator validator)
{
    if (canopen::isNumeric(type)) {
        throw Error(tr("Object %1: %2 is numeric; use add().")
                        .arg(canopen::objectAddress(index, subIndex), canopen::dataTypeName(type)));
    }
    insert(index, subIndex, Entry{type, access, initial, maxSize, std::move(validator)});
}

void ObjectDictionary::insert(quint16 index, quint8 subIndex, Entry entry)
{
    if (contains(index, subIndex)) {
        throw Error(tr("Object %1 is defined twice.").arg(canopen::objectAddress(index, subIndex)));
    }
    m_entries.emplace(key(index, subIndex), std::move(entry));
}

bool ObjectDictionary::contains(quint16 index, quint8 subIndex) const
{
    return find(index, subIndex) != nullptr;
}

bool ObjectDictionary::containsIndex(quint16 index) const
{
    const auto it = m_entries.lower_bound(key(index, 0));
    return it != m_entries.end() && (it->first >> 8) == index;
}

DataType ObjectDictionary::type(quint16 index, quint8 subIndex) const
{
    return entry(index, subIndex).type;
}

quint32 ObjectDictionary::read(quint16 index, quint8 subIndex, QByteArray *out) const
{
    const Entry *e = find(index, subIndex);
    if (!e)
        return missingCode(index);
    if (e->access == Access::WriteOnly)
        return sdoabort::writeOnly;
    if (out)
        *out = e->value;
    return 0;
}

quint32 ObjectDictionary::checkWrite(quint16 index, quint8 subIndex, qint64 size) const
{
    const Entry *e = find(index, subIndex);
    if (!e)
        return missingCode(index);
    if (e->access == Access::ReadOnly || e->access == Access::Constant)
        return sdoabort::readOnly;
    if (size < 0)
        return 0;
    const int fixed = canopen::dataTypeSize(e->type);
    if (fixed > 0 && size != fixed)
        return size > fixed ? sdoabort::lengthTooHigh : sdoabort::lengthTooLow;
    if (fixed == 0 && e->maxSize > 0 && size > e->maxSize)
        return sdoabort::lengthTooHigh;
    return 0;
}

quint32 ObjectDictionary::write(quint16 index, quint8 subIndex, const QByteArray &data)
{
    if (const quint32 code = checkWrite(index, subIndex, data.size()))
        return code;
    Entry &e = m_entries.at(key(index, subIndex));
    if (e.validator) {
        if (const quint32 code = e.validator(data))
            return code;
    }
    e.value = data;
    emit valueWritten(index, subIndex);
    return 0;
}

double ObjectDictionary::value(quint16 index, quint8 subIndex) const
{
    const Entry &e = entry(index, subIndex);
    return canopen::decodeValue(e.type, e.value);
}

void ObjectDictionary::setValue(quint16 index, quint8 subIndex, double value)
{
    const Entry &e = entry(index, subIndex);
    const QByteArray raw = canopen::encodeValue(e.type, value);
    m_entries.at(key(index, subIndex)).value = raw;
}

QByteArray ObjectDictionary::bytes(quint16 index, quint8 subIndex) const
{
    return entry(index, subIndex).value;
}

void ObjectDictionary::setBytes(quint16 index, quint8 subIndex, const QByteArray &bytes)
{
    const Entry &e = entry(index, subIndex);
    const int fixed = canopen::dataTypeSize(e.type);
    if (fixed > 0 && bytes.size() != fixed) {
        throw Error(tr("Object %1 holds %2 bytes, not %3.")
                        .arg(canopen::objectAddress(index, subIndex))
                        .arg(fixed)
                        .arg(bytes.size()));
    }
    m_entries.at(key(index, subIndex)).value = bytes;
}

ObjectDictionary::Validator ObjectDictionary::rangeValidator(DataType type, double min, double max)
{
    return [type, min, max](const QByteArray &raw) -> quint32 {
        const double v = canopen::decodeValue(type, raw);
        if (!(v >= min))
            return v < min ? sdoabort::valueTooLow : sdoabort::invalidValue; // NaN: invalid
        if (v > max)
            return sdoabort::valueTooHigh;
        return 0;
    };
}

const ObjectDictionary::Entry *ObjectDictionary::find(quint16 index, quint8 subIndex) const
{
    const auto it = m_entries.find(key(index, subIndex));
    return it == m_entries.end() ? nullptr : &it->second;
}

const ObjectDictionary::Entry &ObjectDictionary::entry(quint16 index, quint8 subIndex) const
{
    const Entry *e = find(index, subIndex);
    if (!e) {
        throw Error(tr("Object %1 is not in the object dictionary.")
                        .arg(canopen::objectAddress(index, subIndex)));
    }
    return *e;
}

quint32 ObjectDictionary::missingCode(quint16 index) const
{
    return containsIndex(index) ? sdoabort::subIndexDoesNotExist : sdoabort::objectDoesNotExist;
}

} // namespace learnid
