#include "io/ParameterFile.h"

#include "io/AtomicFile.h"
#include "io/JsonReader.h"
#include "io/JsonTree.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QJsonDocument>
#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ParameterFile)
};

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

constexpr double infinity = std::numeric_limits<double>::infinity();

QString indexText(quint16 index)
{
    return QStringLiteral("0x") +
           QString::number(index, 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

JsonTree controllerTree(const ControllerSettings &c)
{
    JsonTree t = JsonTree::object();
    t.insert(key("samplePeriod"), c.samplePeriod)
        .insert(key("kp"), JsonTree::numbers(c.kp))
        .insert(key("ki"), JsonTree::numbers(c.ki))
        .insert(key("kd"), JsonTree::numbers(c.kd))
        .insert(key("lambda"), c.lambda);
    return t;
}

// "data", "prior" or "unknown" for a determined share (LogFit::standardDetermined).
QString determinedSource(double share)
{
    if (!std::isfinite(share))
        return QStringLiteral("unknown");
    return share >= 0.5 ? QStringLiteral("data") : QStringLiteral("prior");
}

double determinedAt(const ParameterFileContent &c, int i)
{
    return c.standardDetermined.empty() ? std::numeric_limits<double>::quiet_NaN()
                                        : c.standardDetermined[size_t(i)];
}

JsonTree standardTree(const ParameterFileContent &c)
{
    JsonTree list = JsonTree::array();
    for (int i = 0; i < int(c.standardParameters.size()); ++i) {
        const ParameterInfo &p = c.standardParameters.at(i);
        const double share = determinedAt(c, i);
        JsonTree o = JsonTree::object();
        o.insert(key("name"), p.name)
            .insert(key("unit"), p.unit)
            .insert(key("description"), p.description)
            .insert(key("value"), c.standardValues[i])
            .insert(key("determined"), share) // NaN -> null
            .insert(key("source"), determinedSource(share));
        list.append(o);
    }
    return list;
}

JsonTree contentTree(const ParameterFileContent &c)
{
    JsonTree nodes = JsonTree::array();
    for (int node : c.nodes())
        nodes.append(node);
    JsonTree robot = JsonTree::object();
    robot.insert(key("model"), c.robotModel)
        .insert(key("description"), c.robotDescription)
        .insert(key("jointNodes"), nodes);
    if (!c.drives.isEmpty()) {
        JsonTree drives = JsonTree::array();
        for (const DriveIdentity &d : c.drives) {
            JsonTree o = JsonTree::object();
            o.insert(key("vendorId"), double(d.vendorId))
                .insert(key("productCode"), double(d.productCode))
                .insert(key("revision"), double(d.revision))
                .insert(key("serialNumber"), double(d.serialNumber));
            drives.append(o);
        }
        robot.insert(key("drives"), drives);
    }
    JsonTree identification = JsonTree::object();
    identification.insert(key("law"), c.law).insert(key("sourceTrial"), c.sourceTrial);
    JsonTree parameters = JsonTree::array();
    for (int i = 0; i < int(c.parameters.size()); ++i) {
        const ParameterInfo &p = c.parameters.at(i);
        JsonTree o = JsonTree::object();
        o.insert(key("name"), p.name)
            .insert(key("unit"), p.unit)
            .insert(key("description"), p.description)
            .insert(key("value"), c.values[i]);
        if (c.standardDeviations.size() > 0)
            o.insert(key("standardDeviation"), c.standardDeviations[i]); // +inf -> null
        parameters.append(o);
    }
    JsonTree quality = JsonTree::object();
    quality.insert(key("maxTrackingErrorDeg"), JsonTree::numbers(c.maxTrackingErrorDeg))
        .insert(key("rmsTrackingErrorDeg"), JsonTree::numbers(c.rmsTrackingErrorDeg))
        .insert(key("residualRms"), JsonTree::numbers(c.residualRms))
        .insert(key("condition"), c.condition)
        .insert(key("rank"), c.rank);
    JsonTree writes = JsonTree::array();
    for (const SdoWrite &w : c.canWrites) {
        JsonTree o = JsonTree::object();
        o.insert(key("node"), w.node)
            .insert(key("index"), indexText(w.index))
            .insert(key("subindex"), int(w.subIndex))
            .insert(key("type"), w.dataType)
            .insert(key("value"), w.value)
            .insert(key("raw"), QString::fromLatin1(w.raw.toHex()));
        writes.append(o);
    }
    JsonTree root = JsonTree::object();
    root.insert(key("schema"), QString::fromLatin1(parameterFileSchema))
        .insert(key("created"), c.created.toUTC().toString(Qt::ISODateWithMs))
        .insert(key("toolVersion"), c.toolVersion)
        .insert(key("robot"), robot)
        .insert(key("controller"), c.hasController ? controllerTree(c.controller) : JsonTree())
        .insert(key("identification"), identification)
        .insert(key("parameters"), parameters)
        .insert(key("standardParameters"), standardTree(c));
    if (c.payload)
        root.insert(key("payload"), payloadSectionTree(*c.payload));
    root.insert(key("quality"), quality).insert(key("canWrites"), writes);
    return root;
}

ControllerSettings readController(JsonObjectReader r)
{
    ControllerSettings c;
    c.samplePeriod = jsonNumber(r.require(key("samplePeriod")), r.keyPath(key("samplePeriod")));
    c.kp = jsonNumbers(r.require(key("kp")), r.keyPath(key("kp")));
    c.ki = jsonNumbers(r.require(key("ki")), r.keyPath(key("ki")));
    c.kd = jsonNumbers(r.require(key("kd")), r.keyPath(key("kd")));
    c.lambda = jsonNumber(r.require(key("lambda")), r.keyPath(key("lambda")));
    r.rejectUnknownKeys();
    return c;
}

void readParameters(const QJsonValue &value, const QString &path, ParameterFileContent &c)
{
    const QJsonArray list = jsonArray(value, path);
    const int m = int(list.size());
    c.values.resize(m);
    c.standardDeviations.resize(m);
    int withStd = 0;
    for (int i = 0; i < m; ++i) {
        JsonObjectReader p(list.at(i), jsonIndexPath(path, i));
        ParameterInfo info;
        info.name = jsonString(p.require(key("name")), p.keyPath(key("name")));
        info.unit = jsonString(p.require(key("unit")), p.keyPath(key("unit")));
        info.description = jsonString(p.require(key("description")), p.keyPath(key("description")));
        c.parameters.append(info);
        c.values[i] = jsonNumber(p.require(key("value")), p.keyPath(key("value")));
        const QJsonValue sd = p.value(key("standardDeviation"));
        if (i > 0 && sd.isUndefined() != (withStd == 0))
            throwAtKey(p.keyPath(key("standardDeviation")),
                       Text::tr("must be given for every parameter or for none"));
        if (!sd.isUndefined()) {
            ++withStd;
            c.standardDeviations[i] =
                sd.isNull() ? infinity : jsonNumber(sd, p.keyPath(key("standardDeviation")));
        }
        p.rejectUnknownKeys();
    }
    if (withStd == 0)
        c.standardDeviations.resize(0);
}

void readStandard(const QJsonValue &value, const QString &path, ParameterFileContent &c)
{
    const QJsonArray list = jsonArray(value, path);
    const int p = int(list.size());
    c.standardValues.resize(p);
    c.standardDetermined.assign(size_t(p), std::numeric_limits<double>::quiet_NaN());
    for (int i = 0; i < p; ++i) {
        JsonObjectReader r(list.at(i), jsonIndexPath(path, i));
        ParameterInfo info;
        info.name = jsonString(r.require(key("name")), r.keyPath(key("name")));
        info.unit = jsonString(r.require(key("unit")), r.keyPath(key("unit")));
        info.description = jsonString(r.require(key("description")), r.keyPath(key("description")));
        c.standardParameters.append(info);
        c.standardValues[i] = jsonNumber(r.require(key("value")), r.keyPath(key("value")));
        const QJsonValue determined = r.require(key("determined"));
        if (!determined.isNull())
            c.standardDetermined[size_t(i)] = jsonNumber(determined, r.keyPath(key("determined")));
        const QString source = jsonString(r.require(key("source")), r.keyPath(key("source")));
        const QString expected = determinedSource(c.standardDetermined[size_t(i)]);
        if (source != expected) {
            throwAtKey(r.keyPath(key("source")),
                       Text::tr("must be \"%1\" for determined %2, got \"%3\"")
                           .arg(expected, describeJsonValue(determined), source));
        }
        r.rejectUnknownKeys();
    }
    // None known reads back as the writer had it: empty.
    if (std::all_of(c.standardDetermined.begin(), c.standardDetermined.end(),
                    [](double share) { return std::isnan(share); }))
        c.standardDetermined.clear();
}

SdoWrite readWrite(JsonObjectReader r)
{
    static const QRegularExpression indexPattern(QStringLiteral("^0x[0-9A-Fa-f]{4}$"));
    static const QRegularExpression hexPattern(QStringLiteral("^([0-9A-Fa-f]{2})+$"));
    SdoWrite w;
    w.node = quint8(jsonInteger(r.require(key("node")), r.keyPath(key("node")), 1, 127));
    const QString index = jsonString(r.require(key("index")), r.keyPath(key("index")));
    if (!indexPattern.match(index).hasMatch()) {
        throwAtKey(
            r.keyPath(key("index")),
            Text::tr("must be an object index written as \"0x\" and four hex digits, got \"%1\"")
                .arg(index));
    }
    w.index = quint16(index.mid(2).toUInt(nullptr, 16));
    w.subIndex =
        quint8(jsonInteger(r.require(key("subindex")), r.keyPath(key("subindex")), 0, 255));
    w.dataType = jsonString(r.require(key("type")), r.keyPath(key("type")));
    w.value = jsonNumber(r.require(key("value")), r.keyPath(key("value")));
    const QString raw = jsonString(r.require(key("raw")), r.keyPath(key("raw")));
    if (!hexPattern.match(raw).hasMatch()) {
        throwAtKey(
            r.keyPath(key("raw")),
            Text::tr("must be the bytes written as pairs of hex digits, got \"%1\"").arg(raw));
    }
    w.raw = QByteArray::fromHex(raw.toLatin1());
    r.rejectUnknownKeys();
    return w;
}

ParameterFileContent readContent(const QJsonObject &root, bool version1)
{
    ParameterFileContent c;
    JsonObjectReader r(root, QString());
    r.value(key("schema"));   // checked before
    r.value(key("checksum")); // checked before
    const QString created = jsonString(r.require(key("created")), key("created"));
    c.created = QDateTime::fromString(created, Qt::ISODateWithMs);
    if (!c.created.isValid()) {
        throwAtKey(key("created"),
                   Text::tr("must be a date and time as in 2024-05-01T12:00:00.000Z, "
                            "got \"%1\"")
                       .arg(created));
    }
    c.toolVersion = jsonString(r.require(key("toolVersion")), key("toolVersion"));

    JsonObjectReader robot = r.object(key("robot"));
    c.robotModel = jsonString(robot.require(key("model")), robot.keyPath(key("model")));
    c.robotDescription =
        jsonString(robot.require(key("description")), robot.keyPath(key("description")));
    const QString nodesPath = robot.keyPath(key("jointNodes"));
    const QJsonArray nodes = jsonArray(robot.require(key("jointNodes")), nodesPath);
    for (int i = 0; i < int(nodes.size()); ++i)
        c.jointNodes.append(int(jsonInteger(nodes.at(i), jsonIndexPath(nodesPath, i), 1, 127)));
    if (const QJsonValue drives = robot.value(key("drives")); !drives.isUndefined()) {
        const QString drivesPath = robot.keyPath(key("drives"));
        const QJsonArray list = jsonArray(drives, drivesPath);
        for (int i = 0; i < int(list.size()); ++i) {
            JsonObjectReader d(list.at(i), jsonIndexPath(drivesPath, i));
            const auto u32 = [&d](const char *name) {
                return quint32(
                    jsonInteger(d.require(key(name)), d.keyPath(key(name)), 0, 0xFFFFFFFFll));
            };
            c.drives.append(
                {u32("vendorId"), u32("productCode"), u32("revision"), u32("serialNumber")});
            d.rejectUnknownKeys();
        }
    }
    robot.rejectUnknownKeys();

    // Version 2 records no gains as null: the identification from logs without a scenario.
    c.hasController = version1 || !r.require(key("controller")).isNull();
    if (c.hasController)
        c.controller = readController(r.object(key("controller")));

    JsonObjectReader identification = r.object(key("identification"));
    c.law = jsonString(identification.require(key("law")), identification.keyPath(key("law")));
    c.sourceTrial = int(jsonInteger(identification.require(key("sourceTrial")),
                                    identification.keyPath(key("sourceTrial")), -1, 1 << 30));
    identification.rejectUnknownKeys();

    readParameters(r.require(key("parameters")), key("parameters"), c);
    if (!version1) {
        readStandard(r.require(key("standardParameters")), key("standardParameters"), c);
        if (auto payload = r.optionalObject(key("payload"))) // version 1 refuses it as unknown
            c.payload = readPayloadSection(*payload);
    }

    JsonObjectReader q = r.object(key("quality"));
    const auto figures = [&q](const char *name) {
        return jsonNumbers(q.require(key(name)), q.keyPath(key(name)), infinity);
    };
    c.maxTrackingErrorDeg = figures("maxTrackingErrorDeg");
    c.rmsTrackingErrorDeg = figures("rmsTrackingErrorDeg");
    c.residualRms = figures("residualRms");
    const QJsonValue condition = q.require(key("condition"));
    c.condition =
        condition.isNull() ? infinity : jsonNumber(condition, q.keyPath(key("condition")));
    c.rank = int(jsonInteger(q.require(key("rank")), q.keyPath(key("rank")), 0, 1 << 30));
    q.rejectUnknownKeys();

    const QJsonArray writes = jsonArray(r.require(key("canWrites")), key("canWrites"));
    for (int i = 0; i < int(writes.size()); ++i)
        c.canWrites.append(
            readWrite(JsonObjectReader(writes.at(i), jsonIndexPath(key("canWrites"), i))));
    r.rejectUnknownKeys();
    return c;
}

// Returns whether the file is of version 1.
bool checkSchemaAndChecksum(QJsonObject root)
{
    const QJsonValue schema = root.value(key("schema"));
    if (schema.isUndefined())
        throwAtKey(key("schema"), Text::tr("is missing; this is not a learnid parameter file"));
    const QString name = jsonString(schema, key("schema"));
    if (name != QLatin1String(parameterFileSchema) &&
        name != QLatin1String(parameterFileSchemaV1)) {
        throwAtKey(key("schema"),
                   Text::tr("this version of learnid reads \"%1\" and \"%2\", got %3")
                       .arg(QLatin1String(parameterFileSchema),
                            QLatin1String(parameterFileSchemaV1), describeJsonValue(schema)));
    }
    const QJsonValue stored = root.value(key("checksum"));
    if (stored.isUndefined())
        throwAtKey(key("checksum"), Text::tr("is missing; this key is required"));
    const QString storedHex = jsonString(stored, key("checksum"));
    root.remove(key("checksum"));
    if (storedHex.compare(QString::fromLatin1(parameterFileChecksum(root)), Qt::CaseInsensitive) !=
        0) {
        throwAtKey(key("checksum"),
                   Text::tr("does not match the content: the file was changed after "
                            "learnid wrote it, or is damaged"));
    }
    return name == QLatin1String(parameterFileSchemaV1);
}

} // namespace

QByteArray parameterFileChecksum(const QJsonObject &withoutChecksum)
{
    const QByteArray canonical = QJsonDocument(withoutChecksum).toJson(QJsonDocument::Compact);
    return QCryptographicHash::hash(canonical, QCryptographicHash::Sha256).toHex();
}

QByteArray parameterFileToJson(const ParameterFileContent &content)
{
    validateParameterFileContent(content);
    JsonTree root = contentTree(content);
    // The checksum covers the file as a reader parses it: Qt's parser turns integral numbers
    // into integers (1e+17 reads back as 100000000000000000), so hash the parsed text, not the
    // values that went in.
    const QJsonObject parsed = QJsonDocument::fromJson(root.toJson()).object();
    root.insert(key("checksum"), QString::fromLatin1(parameterFileChecksum(parsed)));
    return root.toJson();
}

ParameterFileContent parameterFileFromJson(const QByteArray &json, const QString &sourceName)
{
    const QJsonObject root = parseJsonObject(json, sourceName);
    try {
        const bool version1 = checkSchemaAndChecksum(root);
        const ParameterFileContent c = readContent(root, version1);
        validateParameterFileContent(c);
        return c;
    } catch (const Error &e) {
        throw Error(Text::tr("%1: %2").arg(sourceName, e.message()));
    }
}

ParameterFileContent readParameterFile(const QString &path)
{
    return parameterFileFromJson(readFile(path), QDir::toNativeSeparators(path));
}

} // namespace learnid
