#include "io/JsonReader.h"
#include "io/ParameterFile.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <cmath>
#include <limits>

// CiA 306 DCF fragment of the manufacturer objects learnid writes (docs/file-formats.md):
//   0x2100 RECORD  joint controller gains: sub1 kp, sub2 ki, sub3 kd, sub4 lambda (REAL32)
//   0x2200 ARRAY   identified dynamic parameters: sub1..m (REAL32)
// Each drive holds its own joint's gains and the whole parameter vector.
// The text of the fragment is not translated: configuration tools and records compare it.

namespace learnid {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("ParameterFile", text);
}

constexpr quint16 gainsIndex = 0x2100;
constexpr quint16 parametersIndex = 0x2200;

// The shortest decimal text that reads back to the same REAL32 as value.
QByteArray real32Text(double value, const QString &path)
{
    if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max())) {
        throwAtKey(path,
                   tr("does not fit a REAL32 object entry, got %1").arg(describeNumber(value)));
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

struct Entry
{
    QString name;
    QByteArray value;
};

// [IIII] and [IIIIsubN] sections of an ARRAY (0x8) or RECORD (0x9) of REAL32 entries with the
// count in sub0, as CiA 301 lays out such objects.
void writeObject(QByteArray &out, quint16 index, const QString &name, const char *objectType,
                 const QList<Entry> &entries)
{
    const QByteArray section = hex(index);
    const QByteArray count = QByteArray::number(entries.size());
    out += "[" + section + "]\n";
    out += "ParameterName=" + name.toUtf8() + "\n";
    out += QByteArray("ObjectType=") + objectType + "\n";
    out += "SubNumber=" + QByteArray::number(entries.size() + 1) + "\n\n";
    out += "[" + section + "sub0]\n";
    out += "ParameterName=Highest sub-index supported\n";
    out += "ObjectType=0x7\nDataType=0x0005\nAccessType=ro\n";
    out += "DefaultValue=" + count + "\nParameterValue=" + count + "\nPDOMapping=0\n\n";
    for (int i = 0; i < int(entries.size()); ++i) {
        out += "[" + section + "sub" + QByteArray::number(i + 1, 16).toUpper() + "]\n";
        out += "ParameterName=" + entries.at(i).name.toUtf8() + "\n";
        out += "ObjectType=0x7\nDataType=0x0008\nAccessType=rw\n";
        out += "DefaultValue=" + entries.at(i).value + "\n";
        out += "ParameterValue=" + entries.at(i).value + "\nPDOMapping=0\n\n";
    }
}

} // namespace

QByteArray parameterDcfFragment(const ParameterFileContent &content, int joint)
{
    validateParameterFileContent(content);
    const QList<int> nodes = content.nodes();
    if (joint < 0 || joint >= int(nodes.size())) {
        throw Error(tr("DCF fragment: joint %1 does not exist; the robot has %2 joints")
                        .arg(joint + 1)
                        .arg(nodes.size()));
    }
    const ControllerSettings &c = content.controller;
    const QString gainPath = QStringLiteral("controller.%1[%2]");
    const QList<Entry> gains = {
        {QStringLiteral("kp [N m/rad]"),
         real32Text(c.kp[joint], gainPath.arg(QStringLiteral("kp")).arg(joint))},
        {QStringLiteral("ki [N m/(rad s)]"),
         real32Text(c.ki[joint], gainPath.arg(QStringLiteral("ki")).arg(joint))},
        {QStringLiteral("kd [N m s/rad]"),
         real32Text(c.kd[joint], gainPath.arg(QStringLiteral("kd")).arg(joint))},
        {QStringLiteral("lambda [rad/s]"),
         real32Text(c.lambda, QStringLiteral("controller.lambda"))},
    };
    QList<Entry> parameters;
    for (int i = 0; i < int(content.parameters.size()); ++i) {
        const ParameterInfo &p = content.parameters.at(i);
        parameters.append(
            {QStringLiteral("%1 [%2]").arg(p.name, p.unit),
             real32Text(content.values[i], QStringLiteral("parameters[%1].value").arg(i))});
    }

    const QString comments =
        QStringLiteral(
            "; learnid identified parameters, CiA 306 DCF fragment for node %1 (joint %2)\n"
            "; robot %3, law %4, created %5, learnid %6\n")
            .arg(nodes.at(joint))
            .arg(joint + 1)
            .arg(content.robotModel, content.law,
                 content.created.toUTC().toString(Qt::ISODateWithMs), content.toolVersion);
    QByteArray out = comments.toUtf8();
    out += "[DeviceComissioning]\nNodeID=" + QByteArray::number(nodes.at(joint)) + "\n\n";
    out += "[ManufacturerObjects]\nSupportedObjects=2\n";
    out += "1=0x" + hex(gainsIndex) + "\n2=0x" + hex(parametersIndex) + "\n\n";
    writeObject(out, gainsIndex, QStringLiteral("Joint controller gains"), "0x9", gains);
    writeObject(out, parametersIndex, QStringLiteral("Identified dynamic parameters"), "0x8",
                parameters);
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
