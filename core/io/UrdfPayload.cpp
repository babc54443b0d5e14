// A payload as a link fixed to one of the arm's links, added to the arm's URDF text
// (UrdfPayload.h). The comment is not translated: it is part of the file (UrdfExport.cpp).
#include "io/UrdfPayload.h"

#include "model/Error.h"
#include "model/Payload.h"
#include "model/PhysicalConsistency.h"
#include "model/UrdfChain.h"

#include <QCoreApplication>
#include <QLocale>
#include <QSet>
#include <QXmlStreamReader>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(UrdfExport)
};

QString number(double v)
{
    return QString::number(v, 'g', QLocale::FloatingPointShortest);
}

// The names of the document's links and joints, so that the payload's do not clash.
QSet<QString> usedNames(const QByteArray &xml)
{
    QSet<QString> names;
    QXmlStreamReader reader(xml);
    while (!reader.atEnd()) {
        if (reader.readNext() == QXmlStreamReader::StartElement &&
            (reader.name() == QLatin1String("link") || reader.name() == QLatin1String("joint")))
            names.insert(reader.attributes().value(QLatin1String("name")).toString());
    }
    return names;
}

QString uniqueName(const QSet<QString> &used, const char *base)
{
    QString name = QLatin1String(base);
    for (int i = 2; used.contains(name); ++i)
        name = QLatin1String(base) + QLatin1Char('_') + QString::number(i);
    return name;
}

QString escaped(const QString &text)
{
    return text.toHtmlEscaped();
}

QString payloadElements(const QString &link, const QString &linkName, const QString &jointName,
                        const PayloadBody &body, const QString &comment)
{
    QString note = comment;
    while (note.contains(QLatin1String("--"))) // not allowed in an XML comment
        note.replace(QLatin1String("--"), QLatin1String("- -"));
    const Eigen::Matrix3d &i = body.inertiaAtCom;
    QString t;
    if (!note.isEmpty())
        t += QStringLiteral("  <!-- %1 -->\n").arg(note);
    t += QStringLiteral("  <joint name=\"%1\" type=\"fixed\">\n"
                        "    <parent link=\"%2\"/>\n"
                        "    <child link=\"%3\"/>\n"
                        "    <origin rpy=\"0 0 0\" xyz=\"0 0 0\"/>\n"
                        "  </joint>\n")
             .arg(escaped(jointName), escaped(link), escaped(linkName));
    t += QStringLiteral("  <link name=\"%1\">\n"
                        "    <inertial>\n"
                        "      <origin rpy=\"0 0 0\" xyz=\"%2 %3 %4\"/>\n"
                        "      <mass value=\"%5\"/>\n")
             .arg(escaped(linkName), number(body.com.x()), number(body.com.y()),
                  number(body.com.z()), number(body.mass));
    t += QStringLiteral("      <inertia ixx=\"%1\" ixy=\"%2\" ixz=\"%3\" iyy=\"%4\" iyz=\"%5\" "
                        "izz=\"%6\"/>\n"
                        "    </inertial>\n"
                        "  </link>\n")
             .arg(number(i(0, 0)), number(i(0, 1)), number(i(0, 2)), number(i(1, 1)),
                  number(i(1, 2)), number(i(2, 2)));
    return t;
}

} // namespace

QByteArray urdfWithPayload(const QByteArray &xml, const QString &source, const SerialChain &chain,
                           const QString &link, const InertialParameters &payload,
                           const QString &comment)
{
    const SerialChain before = parseUrdfChain(xml, source, chain.baseLink, chain.tipLink);
    const PayloadLink where = payloadLinkOf(before, link);
    const int k = where.joint;
    const QString &linkName = where.name;
    if (!payload.allFinite() || !(payload[0] > 0.0) ||
        !checkConsistency(payload, 1, 1e-12).front().consistent) {
        throw Error(Text::tr("%1: the payload on link \"%2\" is not a real body (mass %3 kg)")
                        .arg(source, linkName)
                        .arg(payload[0]));
    }
    const qsizetype end = xml.lastIndexOf("</robot>");
    if (end < 0)
        throw Error(Text::tr("%1: no closing </robot> to add the payload before").arg(source));
    const QSet<QString> used = usedNames(xml);
    const QString elements =
        payloadElements(linkName, uniqueName(used, urdfPayloadLinkName),
                        uniqueName(used, urdfPayloadJointName), payloadBody(payload), comment);
    QByteArray out = xml;
    out.insert(end, elements.toUtf8());

    const SerialChain after = parseUrdfChain(out, source, chain.baseLink, chain.tipLink);
    for (int j = 0; j < before.dof(); ++j) {
        const InertialParameters expected =
            before.joints[size_t(j)].inertial +
            (j == k ? payloadInBody(where, payload) : InertialParameters::Zero());
        const InertialParameters &read = after.joints.at(size_t(j)).inertial;
        if ((read - expected).cwiseAbs().maxCoeff() > 1e-9 * expected.cwiseAbs().maxCoeff()) {
            throw Error(Text::tr("%1: the URDF with the payload reads back with another body at "
                                 "link \"%2\" than was written")
                            .arg(source, after.joints.at(size_t(j)).link));
        }
    }
    return out;
}

} // namespace learnid
