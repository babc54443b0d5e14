#pragma once

#include <Eigen/Core>
#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>
#include <optional>
#include <utility>

namespace learnid {

// Reading JSON files strictly, naming every problem by its key path ("controller.kp[1]"). The
// functions throw learnid::Error("<key path>: <what is wrong>"); the file readers put the source
// name in front. Used by the io readers only.

/// "parent.key", or "key" at the top level.
QString jsonKeyPath(const QString &parent, const QString &key);
/// "parent[index]".
QString jsonIndexPath(const QString &parent, int index);

/// Throws Error("<path>: <what>").
[[noreturn]] void throwAtKey(const QString &path, const QString &what);

/// A number as messages show it: -5, 0.002, inf, nan.
QString describeNumber(double value);
/// A JSON value as messages show it: -5, "nan", true, null, an array, an object.
QString describeJsonValue(const QJsonValue &value);
/// "an integer from lo to hi", for messages.
QString integerRangeText(qint64 lo, qint64 hi);

/// Parses a document whose top level must be an object. Throws Error naming sourceName and, for
/// a syntax error, the line, the column and the byte offset where the parser stopped. A number
/// beyond the range of a double (1e999), which Qt's parser refuses, is kept as a marked value
/// that the typed readers below report by key path.
QJsonObject parseJsonObject(const QByteArray &json, const QString &sourceName);

/// A finite number. JSON has no NaN or inf: 1e999 is refused as beyond the range of a double, and
/// strings such as "nan" are not numbers.
double jsonNumber(const QJsonValue &value, const QString &path);
/// An integral number in [lo, hi] (|hi|, |lo| <= 2^53). allowed replaces "an integer from lo to
/// hi" in the message when the allowed set is more particular.
qint64 jsonInteger(const QJsonValue &value, const QString &path, qint64 lo, qint64 hi,
                   const QString &allowed = {});
QString jsonString(const QJsonValue &value, const QString &path);
/// A string that is one of names: its index. The message names them all: must be "a", "b" or
/// "c", got "d".
int jsonChoice(const QJsonValue &value, const QString &path, const QStringList &names);
/// A setting's enumerator from its name in table ({enumerator, name} pairs), by jsonChoice().
template <typename E, size_t N>
E jsonEnum(const QJsonValue &value, const QString &path,
           const std::pair<E, const char *> (&table)[N])
{
    QStringList names;
    for (const auto &entry : table)
        names << QLatin1String(entry.second);
    return table[jsonChoice(value, path, names)].first;
}
/// The name of e in table, as jsonEnum() reads it ("" when e is not in the table).
template <typename E, size_t N> QString enumName(E e, const std::pair<E, const char *> (&table)[N])
{
    for (const auto &entry : table)
        if (entry.first == e)
            return QString::fromLatin1(entry.second);
    return {};
}
bool jsonBool(const QJsonValue &value, const QString &path);
QJsonArray jsonArray(const QJsonValue &value, const QString &path);
/// An array of finite numbers, any length. With nullAs, null entries read as *nullAs (the
/// writers put null where a figure is +inf).
Eigen::VectorXd jsonNumbers(const QJsonValue &value, const QString &path,
                            std::optional<double> nullAs = {});

/// The members of one JSON object. Every key asked for is remembered, so that
/// rejectUnknownKeys() can refuse the others (a misspelt key must not silently become a
/// default) and list the allowed ones.
class JsonObjectReader
{
public:
    /// Throws when value is not an object.
    JsonObjectReader(const QJsonValue &value, const QString &path);

    const QString &path() const { return m_path; }
    QString keyPath(const QString &key) const { return jsonKeyPath(m_path, key); }
    bool contains(const QString &key) const { return m_object.contains(key); }

    /// The member, or Undefined when absent; the key becomes known either way.
    QJsonValue value(const QString &key);
    /// The member; throws when absent.
    QJsonValue require(const QString &key);
    /// The member object; throws when absent or not an object.
    JsonObjectReader object(const QString &key);
    /// The member object when present.
    std::optional<JsonObjectReader> optionalObject(const QString &key);

    // Optional members: out keeps its value (the default) when the key is absent.
    void read(const QString &key, double &out);
    void read(const QString &key, QString &out);
    void read(const QString &key, bool &out);
    void read(const QString &key, Eigen::VectorXd &out);
    template <typename Int>
    void readInteger(const QString &key, Int &out, qint64 lo, qint64 hi,
                     const QString &allowed = {})
    {
        const QJsonValue v = value(key);
        if (!v.isUndefined())
            out = Int(jsonInteger(v, keyPath(key), lo, hi, allowed));
    }

    /// Throws on the first member that no call above asked for.
    void rejectUnknownKeys() const;

private:
    QJsonObject m_object;
    QString m_path;
    QStringList m_known;
};

} // namespace learnid
