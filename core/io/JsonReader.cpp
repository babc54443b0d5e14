#include "io/JsonReader.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QLocale>
#include <QRegularExpression>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(JsonReader)
};

// Qt's parser refuses a well-formed number beyond the range of a double (1e999) as a syntax
// error, which cannot name the key. parseJsonObject() puts such a number in a string behind this
// prefix and parses again, so that the typed readers report it by key path.
const QLatin1String outOfRangeMarker("\x01"
                                     "learnid-out-of-range:");

bool isNumberChar(char c)
{
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

// The number text behind the marker, or an empty string for any other value.
QString outOfRangeNumber(const QJsonValue &value)
{
    const QString s = value.toString();
    return value.isString() && s.startsWith(outOfRangeMarker) ? s.mid(outOfRangeMarker.size())
                                                              : QString();
}

// Replaces the well-formed number that ends at end (where Qt's parser stops) by a marked string
// and returns the bytes added; 0 when there is no such number.
int markOutOfRangeNumber(QByteArray &text, int end)
{
    static const QRegularExpression number(
        QStringLiteral("^-?(0|[1-9][0-9]*)(\\.[0-9]+)?([eE][+-]?[0-9]+)?$"));
    int start = end;
    while (start > 0 && isNumberChar(text.at(start - 1)))
        --start;
    const QByteArray token = text.mid(start, end - start);
    if (token.isEmpty() || !number.match(QString::fromLatin1(token)).hasMatch())
        return 0;
    const QByteArray marked = "\"\\u0001learnid-out-of-range:" + token + '"';
    text.replace(start, end - start, marked);
    return int(marked.size() - token.size());
}

} // namespace

QString jsonKeyPath(const QString &parent, const QString &key)
{
    return parent.isEmpty() ? key : parent + QLatin1Char('.') + key;
}

QString jsonIndexPath(const QString &parent, int index)
{
    return parent + QLatin1Char('[') + QString::number(index) + QLatin1Char(']');
}

void throwAtKey(const QString &path, const QString &what)
{
    throw Error(QStringLiteral("%1: %2").arg(path, what));
}

QString describeNumber(double value)
{
    return QString::number(value, 'g', QLocale::FloatingPointShortest);
}

QString describeJsonValue(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return describeNumber(value.toDouble());
    case QJsonValue::String: {
        const QString outOfRange = outOfRangeNumber(value);
        if (!outOfRange.isEmpty())
            return Text::tr("%1 (beyond the range of a double)").arg(outOfRange);
        QString s = value.toString();
        if (s.size() > 40)
            s = s.left(37) + QStringLiteral("...");
        return QLatin1Char('"') + s + QLatin1Char('"');
    }
    case QJsonValue::Array:
        return Text::tr("an array");
    case QJsonValue::Object:
        return Text::tr("an object");
    case QJsonValue::Undefined:
        break;
    }
    return Text::tr("nothing");
}

QString integerRangeText(qint64 lo, qint64 hi)
{
    return Text::tr("an integer from %1 to %2").arg(lo).arg(hi);
}

QJsonObject parseJsonObject(const QByteArray &json, const QString &sourceName)
{
    if (json.trimmed().isEmpty())
        throw Error(Text::tr("%1: the file is empty; expected a JSON object").arg(sourceName));
    QByteArray text = json;
    int added = 0; // by marking numbers; all of them lie before a later syntax error
    QJsonParseError parseError;
    QJsonDocument doc = QJsonDocument::fromJson(text, &parseError);
    for (int marked = 0; parseError.error == QJsonParseError::IllegalNumber && marked < 1000;
         ++marked) {
        const int more = markOutOfRangeNumber(text, parseError.offset);
        if (more == 0)
            break;
        added += more;
        doc = QJsonDocument::fromJson(text, &parseError);
    }
    if (parseError.error != QJsonParseError::NoError) {
        const int offset = qBound(0, parseError.offset - added, int(json.size()));
        const QByteArray before = json.left(offset);
        const int line = int(before.count('\n')) + 1;
        const int column = offset - int(before.lastIndexOf('\n') + 1) + 1;
        throw Error(Text::tr("%1: invalid JSON at line %2, column %3 (byte offset %4): %5")
                        .arg(sourceName)
                        .arg(line)
                        .arg(column)
                        .arg(offset)
                        .arg(parseError.errorString()));
    }
    if (!doc.isObject()) {
        throw Error(Text::tr("%1: the top level must be a JSON object, got %2")
                        .arg(sourceName,
                             doc.isArray() ? Text::tr("an array") : Text::tr("a single value")));
    }
    return doc.object();
}

double jsonNumber(const QJsonValue &value, const QString &path)
{
    const QString outOfRange = outOfRangeNumber(value);
    if (!outOfRange.isEmpty()) {
        throwAtKey(
            path, Text::tr("must be a finite number, got %1, which is beyond the range of a double")
                      .arg(outOfRange));
    }
    if (!value.isDouble())
        throwAtKey(path, Text::tr("must be a number, got %1").arg(describeJsonValue(value)));
    const double v = value.toDouble();
    if (!std::isfinite(v))
        throwAtKey(path, Text::tr("must be a finite number, got %1").arg(describeNumber(v)));
    return v;
}

qint64 jsonInteger(const QJsonValue &value, const QString &path, qint64 lo, qint64 hi,
                   const QString &allowed)
{
    const QString expected = allowed.isEmpty() ? integerRangeText(lo, hi) : allowed;
    const auto fail = [&] {
        throwAtKey(path, Text::tr("must be %1, got %2").arg(expected, describeJsonValue(value)));
    };
    if (!value.isDouble())
        fail();
    const double d = value.toDouble();
    // Compare as doubles first, so that a huge number is never converted to qint64.
    if (!std::isfinite(d) || d != std::floor(d) || d < double(lo) || d > double(hi))
        fail();
    const qint64 i = value.toInteger(qint64(d)); // exact when the text was an integer
    if (i < lo || i > hi)
        fail();
    return i;
}

QString jsonString(const QJsonValue &value, const QString &path)
{
    if (!value.isString())
        throwAtKey(path, Text::tr("must be a string, got %1").arg(describeJsonValue(value)));
    return value.toString();
}

int jsonChoice(const QJsonValue &value, const QString &path, const QStringList &names)
{
    const int index = int(names.indexOf(jsonString(value, path)));
    if (index >= 0)
        return index;
    QStringList quoted;
    for (const QString &name : names)
        quoted << QLatin1Char('"') + name + QLatin1Char('"');
    const QString last = quoted.takeLast();
    const QString allowed =
        quoted.isEmpty() ? last : Text::tr("%1 or %2").arg(quoted.join(QStringLiteral(", ")), last);
    throwAtKey(path, Text::tr("must be %1, got %2").arg(allowed, describeJsonValue(value)));
}

bool jsonBool(const QJsonValue &value, const QString &path)
{
    if (!value.isBool())
        throwAtKey(path, Text::tr("must be true or false, got %1").arg(describeJsonValue(value)));
    return value.toBool();
}

QJsonArray jsonArray(const QJsonValue &value, const QString &path)
{
    if (!value.isArray())
        throwAtKey(path, Text::tr("must be an array, got %1").arg(describeJsonValue(value)));
    return value.toArray();
}

Eigen::VectorXd jsonNumbers(const QJsonValue &value, const QString &path,
                            std::optional<double> nullAs)
{
    const QJsonArray a = jsonArray(value, path);
    Eigen::VectorXd v(a.size());
    for (int i = 0; i < int(a.size()); ++i) {
        if (nullAs && a.at(i).isNull())
            v[i] = *nullAs;
        else
            v[i] = jsonNumber(a.at(i), jsonIndexPath(path, i));
    }
    return v;
}

JsonObjectReader::JsonObjectReader(const QJsonValue &value, const QString &path)
    : m_path(path)
{
    if (!value.isObject())
        throwAtKey(path, Text::tr("must be an object, got %1").arg(describeJsonValue(value)));
    m_object = value.toObject();
}

QJsonValue JsonObjectReader::value(const QString &key)
{
    if (!m_known.contains(key))
        m_known.append(key);
    return m_object.value(key);
}

QJsonValue JsonObjectReader::require(const QString &key)
{
    const QJsonValue v = value(key);
    if (v.isUndefined())
        throwAtKey(keyPath(key), Text::tr("is missing; this key is required"));
    return v;
}

JsonObjectReader JsonObjectReader::object(const QString &key)
{
    return JsonObjectReader(require(key), keyPath(key));
}

std::optional<JsonObjectReader> JsonObjectReader::optionalObject(const QString &key)
{
    const QJsonValue v = value(key);
    if (v.isUndefined())
        return std::nullopt;
    return JsonObjectReader(v, keyPath(key));
}

void JsonObjectReader::read(const QString &key, double &out)
{
    const QJsonValue v = value(key);
    if (!v.isUndefined())
        out = jsonNumber(v, keyPath(key));
}

void JsonObjectReader::read(const QString &key, QString &out)
{
    const QJsonValue v = value(key);
    if (!v.isUndefined())
        out = jsonString(v, keyPath(key));
}

void JsonObjectReader::read(const QString &key, bool &out)
{
    const QJsonValue v = value(key);
    if (!v.isUndefined())
        out = jsonBool(v, keyPath(key));
}

void JsonObjectReader::read(const QString &key, Eigen::VectorXd &out)
{
    const QJsonValue v = value(key);
    if (!v.isUndefined())
        out = jsonNumbers(v, keyPath(key));
}

void JsonObjectReader::rejectUnknownKeys() const
{
    for (auto it = m_object.begin(); it != m_object.end(); ++it) {
        if (!m_known.contains(it.key())) {
            throwAtKey(
                jsonKeyPath(m_path, it.key()),
                Text::tr("unknown key; allowed here: %1").arg(m_known.join(QStringLiteral(", "))));
        }
    }
}

} // namespace learnid
