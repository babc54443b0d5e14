#include "io/JsonTree.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QLocale>
#include <cmath>

namespace learnid {

JsonTree::JsonTree(double value)
    : m_scalar(std::isfinite(value) ? QJsonValue(value) : QJsonValue(QJsonValue::Null))
{}

JsonTree::JsonTree(int value)
    : m_scalar(value)
{}

JsonTree::JsonTree(qint64 value)
    : m_scalar(value)
{}

JsonTree::JsonTree(bool value)
    : m_scalar(value)
{}

JsonTree::JsonTree(const QString &value)
    : m_scalar(value)
{}

JsonTree JsonTree::object()
{
    JsonTree t;
    t.m_kind = Kind::Object;
    return t;
}

JsonTree JsonTree::array()
{
    JsonTree t;
    t.m_kind = Kind::Array;
    return t;
}

JsonTree JsonTree::numbers(const Eigen::VectorXd &values)
{
    JsonTree t = array();
    for (Eigen::Index i = 0; i < values.size(); ++i)
        t.append(JsonTree(values[i]));
    return t;
}

JsonTree &JsonTree::insert(const QString &key, const JsonTree &value)
{
    Q_ASSERT(m_kind == Kind::Object);
    m_keys.append(key);
    m_items.push_back(value);
    return *this;
}

JsonTree &JsonTree::append(const JsonTree &value)
{
    Q_ASSERT(m_kind == Kind::Array);
    m_items.push_back(value);
    return *this;
}

QJsonValue JsonTree::toJsonValue() const
{
    switch (m_kind) {
    case Kind::Scalar:
        return m_scalar;
    case Kind::Array: {
        QJsonArray a;
        for (const JsonTree &item : m_items)
            a.append(item.toJsonValue());
        return a;
    }
    case Kind::Object: {
        QJsonObject o;
        for (size_t i = 0; i < m_items.size(); ++i)
            o.insert(m_keys.at(qsizetype(i)), m_items[i].toJsonValue());
        return o;
    }
    }
    return {};
}

QByteArray JsonTree::toJson() const
{
    QByteArray out;
    write(out, 0);
    out += '\n';
    return out;
}

QByteArray JsonTree::formatNumber(double value)
{
    if (!std::isfinite(value))
        return QByteArrayLiteral("null");
    // Below 2^53 every integral double is exact; print it as an integer, as people write it.
    if (std::abs(value) < 9007199254740992.0 && value == std::floor(value))
        return QByteArray::number(qint64(value));
    return QByteArray::number(value, 'g', QLocale::FloatingPointShortest);
}

QByteArray JsonTree::formatString(const QString &value)
{
    QByteArray out;
    out += '"';
    const QByteArray utf8 = value.toUtf8();
    for (const char c : utf8) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (uchar(c) < 0x20)
                out += "\\u00" + QByteArray::number(uchar(c), 16).rightJustified(2, '0');
            else
                out += c;
        }
    }
    out += '"';
    return out;
}

void JsonTree::write(QByteArray &out, int indent) const
{
    if (m_kind == Kind::Scalar) {
        switch (m_scalar.type()) {
        case QJsonValue::Bool:
            out += m_scalar.toBool() ? "true" : "false";
            return;
        case QJsonValue::Double:
            out += formatNumber(m_scalar.toDouble());
            return;
        case QJsonValue::String:
            out += formatString(m_scalar.toString());
            return;
        default:
            out += "null";
            return;
        }
    }
    const bool isObject = m_kind == Kind::Object;
    if (m_items.empty()) {
        out += isObject ? "{}" : "[]";
        return;
    }
    bool flat = !isObject;
    for (const JsonTree &item : m_items)
        flat = flat && !item.isContainer();
    if (flat) {
        out += '[';
        for (size_t i = 0; i < m_items.size(); ++i) {
            if (i > 0)
                out += ", ";
            m_items[i].write(out, indent);
        }
        out += ']';
        return;
    }
    const QByteArray inner(4 * (indent + 1), ' ');
    out += isObject ? "{\n" : "[\n";
    for (size_t i = 0; i < m_items.size(); ++i) {
        out += inner;
        if (isObject)
            out += formatString(m_keys.at(qsizetype(i))) + ": ";
        m_items[i].write(out, indent + 1);
        out += i + 1 < m_items.size() ? ",\n" : "\n";
    }
    out += QByteArray(4 * indent, ' ');
    out += isObject ? '}' : ']';
}

} // namespace learnid
