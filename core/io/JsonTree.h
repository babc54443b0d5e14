#pragma once

#include <Eigen/Core>
#include <QByteArray>
#include <QJsonValue>
#include <QString>
#include <QStringList>
#include <vector>

namespace learnid {

/// A JSON value whose object members keep the order they were inserted in, so that files people
/// read (scenario, parameter file) list their keys in the documented order; QJsonObject sorts
/// them. Scalars are held as QJsonValue. Used by the io writers only.
class JsonTree
{
public:
    JsonTree() = default; ///< null
    JsonTree(double value);
    JsonTree(int value);
    JsonTree(qint64 value);
    JsonTree(bool value);
    JsonTree(const QString &value);
    JsonTree(const char *) = delete; ///< would silently become a bool; pass a QString

    static JsonTree object();
    static JsonTree array();
    /// An array of numbers; entries that are not finite become null (JSON has no NaN or inf).
    static JsonTree numbers(const Eigen::VectorXd &values);

    /// Appends a member to an object; the caller keeps keys unique.
    JsonTree &insert(const QString &key, const JsonTree &value);
    /// Appends an element to an array.
    JsonTree &append(const JsonTree &value);

    /// The same value as a QJsonValue (object keys then sort, as QJsonObject does).
    QJsonValue toJsonValue() const;
    /// UTF-8 text indented by four spaces, members in insertion order, arrays of scalars on one
    /// line, a final newline. Numbers are written so that they read back to the same double.
    QByteArray toJson() const;

    /// The JSON text of a number: integral values below 2^53 without a fraction, others in the
    /// shortest form that reads back to the same double; null when not finite.
    static QByteArray formatNumber(double value);
    /// The JSON text of a string, quoted and escaped.
    static QByteArray formatString(const QString &value);

private:
    enum class Kind { Scalar, Array, Object };

    void write(QByteArray &out, int indent) const;
    bool isContainer() const { return m_kind != Kind::Scalar; }

    Kind m_kind = Kind::Scalar;
    QJsonValue m_scalar = QJsonValue(QJsonValue::Null);
    QStringList m_keys;            ///< object member names, parallel to m_items
    std::vector<JsonTree> m_items; ///< array elements or object member values
};

} // namespace learnid
