#include "model/UrdfExtension.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QXmlStreamReader>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(UrdfExtension)
};

[[noreturn]] void refuse(const QString &source, const QXmlStreamReader &xml, const QString &what)
{
    throw Error(Text::tr("%1: line %2, column %3: <%4>: %5")
                    .arg(source, QString::number(xml.lineNumber()),
                         QString::number(xml.columnNumber()), QLatin1String(urdfExtensionElement),
                         what));
}

JointExtension readElement(const QString &source, const QXmlStreamReader &xml)
{
    JointExtension e;
    for (const QXmlStreamAttribute &a : xml.attributes()) {
        const QString name = a.qualifiedName().toString();
        double *target = name == QLatin1String("armature") ? &e.armature
                         : name == QLatin1String("offset") ? &e.offset
                                                           : nullptr;
        if (!target) {
            refuse(source, xml,
                   Text::tr("unknown attribute \"%1\" (the attributes are armature and offset)")
                       .arg(name));
        }
        bool ok = false;
        *target = a.value().trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(*target)) {
            refuse(
                source, xml,
                Text::tr("%1 must be a finite number, got \"%2\"").arg(name, a.value().toString()));
        }
    }
    return e;
}

} // namespace

QHash<QString, JointExtension> readJointExtensions(const QByteArray &text, const QString &source)
{
    QHash<QString, JointExtension> out;
    // Cheap for URDFs without it: the stream reader runs only when the name occurs.
    if (!text.contains(urdfExtensionElement))
        return out;
    QXmlStreamReader xml(text);
    xml.setNamespaceProcessing(false); // urdfdom does not bind prefixes either
    int depth = 0;
    QString joint;     // the <joint> directly below <robot> being read
    bool seen = false; // its extension element was read
    while (!xml.atEnd()) {
        const QXmlStreamReader::TokenType token = xml.readNext();
        if (token == QXmlStreamReader::StartElement) {
            ++depth;
            const QString name = xml.qualifiedName().toString();
            if (depth == 2 && name == QLatin1String("joint")) {
                joint = xml.attributes().value(QLatin1String("name")).toString();
                seen = false;
            } else if (depth == 3 && !joint.isNull() &&
                       name == QLatin1String(urdfExtensionElement)) {
                if (seen)
                    refuse(source, xml, Text::tr("given twice in joint \"%1\"").arg(joint));
                seen = true;
                out.insert(joint, readElement(source, xml));
            }
        } else if (token == QXmlStreamReader::EndElement) {
            if (depth == 2)
                joint = QString();
            --depth;
        }
    }
    return out;
}

} // namespace learnid
