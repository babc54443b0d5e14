#include "io/ScenarioPayload.h"
#include "io/ScenarioFile.h"

#include "io/ValueChecks.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/Payload.h"
#include "model/PayloadPrior.h"

#include <Eigen/Eigenvalues>
#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ScenarioFile)
};

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

// An optional array of exactly `size` numbers; absent leaves out as it is.
void readFixed(JsonObjectReader &r, const char *name, Eigen::VectorXd &out, int size,
               const QString &what)
{
    Eigen::VectorXd v;
    r.read(key(name), v);
    if (!r.contains(key(name)))
        return;
    checkLength(r.keyPath(key(name)), v.size(), size, what);
    out = v;
}

const QString comText()
{
    return Text::tr("x, y and z");
}

const QString inertiaText()
{
    return Text::tr("Ixx, Ixy, Iyy, Ixz, Iyz and Izz");
}

} // namespace

void readPayloadSection(JsonObjectReader r, PayloadSettings &p)
{
    p.enabled = true;
    r.read(key("link"), p.link);
    JsonObjectReader prior = r.object(key("prior"));
    p.mass = jsonNumber(prior.require(key("mass")), prior.keyPath(key("mass")));
    Eigen::VectorXd com = p.com;
    readFixed(prior, "com", com, 3, comText());
    p.com = com;
    readFixed(prior, "inertia", p.inertia, 6, inertiaText());
    prior.rejectUnknownKeys();
    if (auto bound = r.optionalObject(key("bound"))) {
        bound->read(key("radius"), p.radius);
        readFixed(*bound, "box", p.box, 6, Text::tr("x0, y0, z0, x1, y1 and z1"));
        if (bound->contains(key("radius")) && bound->contains(key("box"))) {
            throwAtKey(
                bound->keyPath(key("box")),
                Text::tr("give the bound either as a sphere (radius) or as a box, not both"));
        }
        bound->rejectUnknownKeys();
    }
    r.readInteger(key("baselineTrials"), p.baselineTrials, 0, scenarioLimits::maxIterations);
    if (auto gains = r.optionalObject(key("baselineGains"))) {
        p.baselineKp = jsonNumbers(gains->require(key("kp")), gains->keyPath(key("kp")));
        p.baselineKi = jsonNumbers(gains->require(key("ki")), gains->keyPath(key("ki")));
        p.baselineKd = jsonNumbers(gains->require(key("kd")), gains->keyPath(key("kd")));
        gains->rejectUnknownKeys();
    }
    r.rejectUnknownKeys();
}

void readSimulatedPayload(JsonObjectReader r, SimulatedPayload &p)
{
    p.present = true;
    p.mass = jsonNumber(r.require(key("mass")), r.keyPath(key("mass")));
    Eigen::VectorXd com = p.com, inertia = p.inertia;
    readFixed(r, "com", com, 3, comText());
    readFixed(r, "inertia", inertia, 6, inertiaText());
    p.com = com;
    p.inertia = inertia;
    r.rejectUnknownKeys();
}

JsonTree payloadSectionJson(const PayloadSettings &p)
{
    JsonTree prior = JsonTree::object();
    prior.insert(key("mass"), p.mass).insert(key("com"), JsonTree::numbers(p.com));
    if (p.inertia.size() > 0)
        prior.insert(key("inertia"), JsonTree::numbers(p.inertia));
    JsonTree bound = JsonTree::object();
    if (p.box.size() > 0)
        bound.insert(key("box"), JsonTree::numbers(p.box));
    else
        bound.insert(key("radius"), p.radius);
    JsonTree t = JsonTree::object();
    t.insert(key("link"), p.link).insert(key("prior"), prior).insert(key("bound"), bound);
    if (p.baselineTrials > 0)
        t.insert(key("baselineTrials"), p.baselineTrials);
    if (p.baselineKp.size() > 0) {
        JsonTree gains = JsonTree::object();
        gains.insert(key("kp"), JsonTree::numbers(p.baselineKp))
            .insert(key("ki"), JsonTree::numbers(p.baselineKi))
            .insert(key("kd"), JsonTree::numbers(p.baselineKd));
        t.insert(key("baselineGains"), gains);
    }
    return t;
}

JsonTree simulatedPayloadJson(const SimulatedPayload &p)
{
    JsonTree t = JsonTree::object();
    t.insert(key("mass"), p.mass)
        .insert(key("com"), JsonTree::numbers(p.com))
        .insert(key("inertia"), JsonTree::numbers(p.inertia));
    return t;
}

void validateScenarioPayload(const Scenario &s, const RobotModel &model)
{
    if (!s.payload.enabled && !s.simulation.payload.present)
        return;
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain) {
        throwAtKey(key(s.payload.enabled ? "payload" : "simulation.payload"),
                   Text::tr("only a URDF robot carries a payload (the model is %1)").arg(s.model));
    }
    if (s.payload.enabled) {
        if (s.payload.inertia.size() != 0)
            checkLength(key("payload.prior.inertia"), s.payload.inertia.size(), 6, inertiaText());
        if (s.payload.box.size() != 0)
            checkLength(key("payload.bound.box"), s.payload.box.size(), 6,
                        Text::tr("x0, y0, z0, x1, y1 and z1"));
        validatePayloadPrior(payloadPriorOf(s.payload));
        const PayloadSettings &p = s.payload;
        if (p.baselineKp.size() + p.baselineKi.size() + p.baselineKd.size() > 0) {
            validateJointGains(p.baselineKp, p.baselineKi, p.baselineKd, model.dof(),
                               key("payload.baselineGains"));
        }
    }
    try {
        payloadJointOf(chain->chain(), s.payload.link);
    } catch (const Error &e) {
        throwAtKey(key("payload.link"), e.message());
    }
    const SimulatedPayload &sim = s.simulation.payload;
    if (!sim.present)
        return;
    checkPositive(key("simulation.payload.mass"), sim.mass);
    for (int i = 0; i < 3; ++i)
        checkFinite(jsonIndexPath(key("simulation.payload.com"), i), sim.com[i]);
    for (int i = 0; i < 6; ++i)
        checkFinite(jsonIndexPath(key("simulation.payload.inertia"), i), sim.inertia[i]);
    const Eigen::Vector3d moments =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertiaFromEntries(sim.inertia))
            .eigenvalues();
    const double tolerance = 1e-12 * moments.cwiseAbs().maxCoeff();
    if (!(moments[0] >= -tolerance) || !(moments[0] + moments[1] >= moments[2] - tolerance)) {
        throwAtKey(key("simulation.payload.inertia"),
                   Text::tr("not a real body's inertia (principal moments %1, %2, %3 kg m^2 must "
                            "not be negative and each at most the sum of the others)")
                       .arg(moments[0])
                       .arg(moments[1])
                       .arg(moments[2]));
    }
}

} // namespace learnid
