#include "can/ManufacturerObjects.h"
#include "can/PayloadObjects.h"
#include "io/JsonReader.h"
#include "io/ParameterFile.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QMap>
#include <cmath>
#include <limits>

// CiA 306 DCF fragment of the manufacturer objects learnid writes (docs/file-formats.md), one
// per drive, generated from the same table as the simulated drive's dictionary
// (objects::manufacturerObjects): 0x2100 the joint's gains (RECORD), 0x2200 the identified
// parameters with their count in sub 0 (ARRAY), and 0x2500 the payload (RECORD) when the file's
// canWrites write one. Each drive holds its own joint's gains and the whole parameter vector.
// 0x2300 (torque limit) is not in a parameter file, so not here.
// The text of the fragment is not translated: configuration tools and records compare it.

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ParameterFile)
};

// The shortest decimal text that reads back to the same REAL32 as value.
QByteArray real32Text(double value, const QString &path)
{
    if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max())) {
        throwAtKey(
            path,
            Text::tr("does not fit a REAL32 object entry, got %1").arg(describeNumber(value)));
    }
    const float f = float(value);
    if (f == std::floor(f) && std::abs(f) < 16777216.0f) // integral and exact in a float
        return QByteArray::number(qint64(f));
    for (int digits = 1; digits < 9; ++digits) {
        const QByteArray text = QByteArray::number(double(f), 'g', digits);
        if (text.toFloat() == f)
            return text;
    }
    return QByteArray::number(double(f), 'g', 9); // always enough for a float
}

QByteArray hex(quint16 index)
{
    return QByteArray::number(index, 16).rightJustified(4, '0').toUpper();
}

// An entry's value as DCF text: integers as such, REAL32 as the shortest text of the same float.
QByteArray valueText(canopen::DataType type, double value, const QString &path)
{
    if (type == canopen::DataType::Real32)
        return real32Text(value, path);
    return QByteArray::number(qint64(value));
}

QByteArray dataTypeText(canopen::DataType type)
{
    return "0x" + QByteArray::number(quint16(type), 16).rightJustified(4, '0').toUpper();
}

QByteArray accessText(ObjectDictionary::Access access)
{
    switch (access) {
    case ObjectDictionary::Access::ReadOnly:
        return "ro";
    case ObjectDictionary::Access::WriteOnly:
        return "wo";
    case ObjectDictionary::Access::ReadWrite:
        return "rw";
    case ObjectDictionary::Access::Constant:
        return "const";
    }
    return "rw";
}

// The key path of gain entry sub in the parameter file's JSON form, for error messages.
QString gainKeyPath(quint8 sub, int joint)
{
    switch (sub) {
    case objects::gainKp:
        return QStringLiteral("controller.kp[%1]").arg(joint);
    case objects::gainKi:
        return QStringLiteral("controller.ki[%1]").arg(joint);
    case objects::gainKd:
        return QStringLiteral("controller.kd[%1]").arg(joint);
    case objects::gainLambda:
        return QStringLiteral("controller.lambda");
    default:
        return {};
    }
}

struct Entry
{
    objects::ObjectDescription object;
    QString name;
    QByteArray value; ///< ParameterValue
};

// [IIII] and [IIIIsubN] sections of an ARRAY or RECORD (sub 0 first), as CiA 306 lays them out.
void writeObject(QByteArray &out, quint16 index, const QString &name, const QList<Entry> &entries)
{
    const QByteArray section = hex(index);
    out += "[" + section + "]\n";
    out += "ParameterName=" + name.toUtf8() + "\n";
    out += "ObjectType=0x" + QByteArray::number(objects::objectCode(index), 16) + "\n";
    out += "SubNumber=" + QByteArray::number(entries.size()) + "\n\n";
    for (const Entry &e : entries) {
        const objects::ObjectDescription &o = e.object;
        out += "[" + section + "sub" + QByteArray::number(o.subIndex, 16).toUpper() + "]\n";
        out += "ParameterName=" + e.name.toUtf8() + "\n";
        out += "ObjectType=0x7\nDataType=" + dataTypeText(o.type) + "\n";
        out += "AccessType=" + accessText(o.access) + "\n";
        out += "DefaultValue=" + valueText(o.type, o.defaultValue, {}) + "\n";
        out += "ParameterValue=" + e.value + "\nPDOMapping=0\n\n";
    }
}

// The payload object's entries with the values the file's canWrites send to node (those are
// payloadWrites(): in the body frame the drive takes, which the file's payload section, about
// its own link, is not). None when no write goes to 0x2500 on that node.
QList<Entry> payloadEntries(const ParameterFileContent &content, int node)
{
    QMap<quint8, const SdoWrite *> written;
    for (const SdoWrite &w : content.canWrites)
        if (w.node == node && w.index == objects::payload)
            written.insert(w.subIndex, &w);
    if (written.isEmpty())
        return {};
    QList<Entry> entries;
    for (const objects::ObjectDescription &o : objects::payloadObjectDescriptions()) {
        const QString name =
            o.unit.isEmpty() ? o.name : QStringLiteral("%1 [%2]").arg(o.name, o.unit);
        const SdoWrite *w = written.value(o.subIndex);
        const QString path = QStringLiteral("canWrites (node %1, 0x2500:%2)")
                                 .arg(node)
                                 .arg(o.subIndex, 2, 16, QLatin1Char('0'));
        if (o.subIndex > 0 && !w)
            throwAtKey(path, Text::tr("the payload object is written in part"));
        entries.append(
            {o, name,
             w ? valueText(o.type, w->value, path) : valueText(o.type, o.defaultValue, {})});
    }
    return entries;
}

} // namespace

QByteArray parameterDcfFragment(const ParameterFileContent &content, int joint)
{
    validateParameterFileContent(content);
    const QList<int> nodes = content.nodes();
    if (joint < 0 || joint >= int(nodes.size())) {
        throw Error(Text::tr("DCF fragment: joint %1 does not exist; the robot has %2 joints")
                        .arg(joint + 1)
                        .arg(nodes.size()));
    }
    const ControllerSettings &c = content.controller;
    objects::ManufacturerDefaults defaults;
    if (content.hasController) {
        defaults.kp = c.kp[joint];
        defaults.ki = c.ki[joint];
        defaults.kd = c.kd[joint];
        defaults.lambda = c.lambda;
    }
    defaults.parameterCount = int(content.parameters.size());
    // What the drive holds once configured and applied: the gains (its defaults here, as the
    // robot side is set up from the same controller), the count and the identified values.
    const auto parameterValue = [&](const objects::ObjectDescription &o) -> QByteArray {
        if (o.index == objects::identifiedParameters && o.subIndex > 0) {
            const int i = o.subIndex - 1;
            return real32Text(content.values[i], QStringLiteral("parameters[%1].value").arg(i));
        }
        if (o.index == objects::identifiedParameters)
            return QByteArray::number(content.parameters.size());
        return valueText(o.type, o.defaultValue, gainKeyPath(o.subIndex, joint));
    };
    QList<Entry> gains;
    QList<Entry> parameters;
    for (const objects::ObjectDescription &o : objects::manufacturerObjects(defaults)) {
        QString name = o.unit.isEmpty() ? o.name : QStringLiteral("%1 [%2]").arg(o.name, o.unit);
        if (o.index == objects::identifiedParameters && o.subIndex > 0) {
            const ParameterInfo &p = content.parameters.at(o.subIndex - 1);
            name = QStringLiteral("%1 [%2]").arg(p.name, p.unit);
        }
        if (o.index == objects::gains)
            gains.append({o, name, parameterValue(o)});
        else if (o.index == objects::identifiedParameters)
            parameters.append({o, name, parameterValue(o)});
    }

    const QString comments =
        QStringLiteral(
            "; learnid identified parameters, CiA 306 DCF fragment for node %1 (joint %2)\n"
            "; robot %3, law %4, created %5, learnid %6\n")
            .arg(nodes.at(joint))
            .arg(joint + 1)
            .arg(content.robotModel, content.law,
                 content.created.toUTC().toString(Qt::ISODateWithMs), content.toolVersion);
    const QList<Entry> payload = payloadEntries(content, nodes.at(joint));
    QByteArray out = comments.toUtf8();
    out += "[DeviceComissioning]\nNodeID=" + QByteArray::number(nodes.at(joint)) + "\n\n";
    // Without recorded gains the fragment holds the identified parameters (and payload) alone.
    QList<quint16> supported;
    if (content.hasController)
        supported << objects::gains;
    supported << objects::identifiedParameters;
    if (!payload.isEmpty())
        supported << objects::payload;
    out += "[ManufacturerObjects]\nSupportedObjects=" + QByteArray::number(supported.size()) + "\n";
    for (qsizetype i = 0; i < supported.size(); ++i)
        out += QByteArray::number(i + 1) + "=0x" + hex(supported[i]) + "\n";
    out += "\n";
    if (content.hasController)
        writeObject(out, objects::gains, QStringLiteral("Joint controller gains"), gains);
    writeObject(out, objects::identifiedParameters, QStringLiteral("Identified dynamic parameters"),
                parameters);
    if (!payload.isEmpty())
        writeObject(out, objects::payload, QStringLiteral("Payload"), payload);
    return out;
}

QByteArray parameterDcfFragment(const ParameterFileContent &content)
{
    QByteArray out;
    for (int j = 0; j < int(content.nodes().size()); ++j)
        out += parameterDcfFragment(content, j);
    return out;
}

} // namespace learnid
