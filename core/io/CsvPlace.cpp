#include "io/CsvPlace.h"

#include "io/JsonReader.h"
#include "model/Error.h"

#include <QCoreApplication>

namespace learnid::csv {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CsvPlace)
};

} // namespace

QString fieldPlace(const QString &source, int line, int column, const QByteArray &name)
{
    QString place = Text::tr("%1: line %2, column %3")
                        .arg(source, QString::number(line), QString::number(column));
    if (!name.isEmpty())
        place += QStringLiteral(" (%1)").arg(QString::fromUtf8(name));
    return place;
}

void throwAtField(const QString &source, int line, int column, const QByteArray &name,
                  const QString &what)
{
    throwAtKey(fieldPlace(source, line, column, name), what);
}

void throwAtLine(const QString &source, int line, const QString &what)
{
    throw Error(Text::tr("%1: line %2: %3").arg(source, QString::number(line), what));
}

QString quoted(const QByteArray &field)
{
    return QLatin1Char('"') + QString::fromUtf8(field.trimmed().left(40)) + QLatin1Char('"');
}

} // namespace learnid::csv
