// The parameter file's "payload" section (docs/file-formats.md, "Payload section").
#include "io/ParameterFilePayload.h"

#include "io/JsonReader.h"
#include "io/JsonTree.h"
#include "io/ValueChecks.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "model/Payload.h"
#include "model/PhysicalConsistency.h"

#include <QCoreApplication>
#include <cmath>

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

const QString section = QStringLiteral("payload");

QString sectionKey(const char *name)
{
    return jsonKeyPath(section, key(name));
}

// The data's values are "data", the prior's "prior", as standardParameters[i].source says.
QString sourceName(bool identified)
{
    return identified ? QStringLiteral("data") : QStringLiteral("prior");
}

// A fixed-length array of numbers (null allowed where nullAs is given).
template <size_t N>
std::array<double, N> fixedNumbers(const QJsonValue &value, const QString &path,
                                   std::optional<double> nullAs = {})
{
    const Eigen::VectorXd v = jsonNumbers(value, path, nullAs);
    checkLength(path, v.size(), Eigen::Index(N), Text::tr("the payload's values"));
    std::array<double, N> out{};
    for (size_t i = 0; i < N; ++i)
        out[i] = v[Eigen::Index(i)];
    return out;
}

Eigen::VectorXd vectorOf(const double *values, int count)
{
    return Eigen::Map<const Eigen::VectorXd>(values, count);
}

} // namespace

InertialParameters ParameterFilePayload::parameters() const
{
    const std::array<double, 6> &i = inertiaAtCom;
    Eigen::Matrix3d ic;
    ic << i[0], i[1], i[3], i[1], i[2], i[4], i[3], i[4], i[5];
    return inertialParameters(mass, com, ic);
}

JsonTree payloadSectionTree(const ParameterFilePayload &p)
{
    JsonTree sources = JsonTree::array();
    for (bool identified : p.identified)
        sources.append(sourceName(identified));
    JsonTree t = JsonTree::object();
    t.insert(key("link"), p.link)
        .insert(key("mass"), p.mass)
        .insert(key("com"), JsonTree::numbers(p.com))
        .insert(key("inertiaAtCom"), JsonTree::numbers(vectorOf(p.inertiaAtCom.data(), 6)))
        .insert(key("source"), sources)
        .insert(key("standardUncertainty"), // NaN -> null
                JsonTree::numbers(vectorOf(p.standardUncertainty.data(), 10)));
    return t;
}

ParameterFilePayload readPayloadSection(JsonObjectReader r)
{
    ParameterFilePayload p;
    p.link = jsonString(r.require(key("link")), r.keyPath(key("link")));
    p.mass = jsonNumber(r.require(key("mass")), r.keyPath(key("mass")));
    const std::array<double, 3> com = fixedNumbers<3>(r.require(key("com")), r.keyPath(key("com")));
    p.com = Eigen::Vector3d(com[0], com[1], com[2]);
    p.inertiaAtCom =
        fixedNumbers<6>(r.require(key("inertiaAtCom")), r.keyPath(key("inertiaAtCom")));
    const QString sourcePath = r.keyPath(key("source"));
    const QJsonArray sources = jsonArray(r.require(key("source")), sourcePath);
    checkLength(sourcePath, sources.size(), 10, Text::tr("the payload's values"));
    for (int i = 0; i < 10; ++i) {
        const QString path = jsonIndexPath(sourcePath, i);
        const QString s = jsonString(sources.at(i), path);
        if (s != sourceName(true) && s != sourceName(false)) {
            throwAtKey(path, Text::tr("must be \"data\" (identified) or \"prior\" (kept at the "
                                      "prior), got \"%1\"")
                                 .arg(s));
        }
        p.identified[size_t(i)] = s == sourceName(true);
    }
    p.standardUncertainty = fixedNumbers<10>(r.require(key("standardUncertainty")),
                                             r.keyPath(key("standardUncertainty")), std::nan(""));
    r.rejectUnknownKeys();
    return p;
}

int checkPayloadLink(const ParameterFilePayload &payload, const SerialChain &chain)
{
    try {
        return payloadJointOf(chain, payload.link);
    } catch (const Error &e) {
        throwAtKey(sectionKey("link"), e.message());
    }
}

void validatePayloadSection(const ParameterFilePayload &p, const QString &robotModel)
{
    if (p.link.isEmpty())
        throwAtKey(sectionKey("link"), Text::tr("must name the link the payload is fixed to"));
    if (!isUrdfModel(robotModel)) {
        throwAtKey(section, Text::tr("the model %1 has no links to fix a payload to; a payload "
                                     "needs a URDF robot")
                                .arg(robotModel));
    }
    if (robotModel != QLatin1String("urdf")) { // a built-in: its links are known here
        const auto model = std::dynamic_pointer_cast<const ChainModel>(makeRobotModel(robotModel));
        if (model)
            checkPayloadLink(p, model->chain());
    }
    checkFinite(sectionKey("mass"), p.mass);
    checkPositive(sectionKey("mass"), p.mass);
    for (int i = 0; i < 3; ++i)
        checkFinite(jsonIndexPath(sectionKey("com"), i), p.com[i]);
    for (int i = 0; i < 6; ++i)
        checkFinite(jsonIndexPath(sectionKey("inertiaAtCom"), i), p.inertiaAtCom[size_t(i)]);
    const LinkConsistency body = checkConsistency(p.parameters(), 1, 1e-12).front();
    if (!body.consistent) {
        throwAtKey(sectionKey("inertiaAtCom"),
                   Text::tr("is not a real body's inertia with this mass and centre of mass (its "
                            "pseudo-inertia has the negative eigenvalue %1)")
                       .arg(body.minEigenvalue));
    }
    for (int i = 0; i < 10; ++i) {
        const QString path = jsonIndexPath(sectionKey("standardUncertainty"), i);
        const double u = p.standardUncertainty[size_t(i)];
        if (std::isnan(u))
            continue;
        if (!p.identified[size_t(i)]) {
            throwAtKey(path, Text::tr("must be null for a value kept at the prior (source[%1] is "
                                      "\"prior\"), got %2")
                                 .arg(i)
                                 .arg(u));
        }
        checkFinite(path, u);
        checkNonNegative(path, u);
    }
}

} // namespace learnid
