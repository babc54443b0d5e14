#include "model/ModelCheck.h"

#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/PhysicalConsistency.h"

#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ModelCheck)
};

QString number(double v)
{
    return QString::number(v, 'g', 3);
}

} // namespace

QString linkLabel(const SerialChain &chain, int l)
{
    return Text::tr("link %1 (%2)").arg(l + 1).arg(chain.joints[size_t(l)].link);
}

QString jointLabel(const SerialChain &chain, int j)
{
    return Text::tr("joint %1 (%2)").arg(j + 1).arg(chain.joints[size_t(j)].name);
}

QStringList linkProblems(const QString &label, const LinkConsistency &c, const LinkPlausibility &v,
                         const std::optional<BoundingEllipsoid> &volume,
                         const PlausibilityRule &rule)
{
    if (!(c.mass > 0.0))
        return {Text::tr("%1: its mass is %2 kg: not a real body").arg(label, number(c.mass))};
    if (!c.consistent) {
        return {Text::tr("%1: no mass distribution has its inertia (its pseudo-inertia has the "
                         "negative eigenvalue %2): not a real body")
                    .arg(label, number(c.minEigenvalue))};
    }
    QStringList out;
    for (const QString &problem : plausibilityProblems(v, volume, rule))
        out << QStringLiteral("%1: %2").arg(label, problem);
    return out;
}

QString jointTermProblem(const QString &label, const QString &term, double value,
                         const PlausibilityRule &rule)
{
    if (value < 0.0) {
        return Text::tr("%1: %2 is %3, negative: friction and rotor inertia take energy, they do "
                        "not give it")
            .arg(label, term, number(value));
    }
    if (value > 0.0 && value < rule.termFloor) {
        return Text::tr("%1: %2 is %3, between 0 and %4: the underflow of a positive "
                        "parametrisation where 0 is meant")
            .arg(label, term, number(value), number(rule.termFloor));
    }
    return {};
}

QStringList modelProblems(const ChainModel &model, const SerialChain &chain,
                          const Eigen::VectorXd &cadPrior, const PlausibilityRule &rule)
{
    const int n = model.dof();
    const Eigen::VectorXd standard = model.standardOf(chain);
    QStringList out;
    const std::vector<LinkConsistency> consistency = checkConsistency(standard, n, 1e-12);
    const auto volumes = linkVolumes(model.chain(), cadPrior);
    const std::vector<LinkPlausibility> plausibility =
        checkPlausibility(standard, cadPrior, n, volumes, rule);
    for (int l = 0; l < n; ++l) {
        out += linkProblems(linkLabel(chain, l), consistency[size_t(l)], plausibility[size_t(l)],
                            volumes[size_t(l)], rule);
    }
    for (int j = 0; j < n; ++j) {
        const ChainJoint &joint = chain.joints[size_t(j)];
        const std::pair<const char *, double> terms[] = {
            {"<dynamics damping>", joint.damping},
            {"<dynamics friction>", joint.friction},
            {"<learnid:dynamics armature>", joint.armature}};
        // Only negative values: a URDF's small positive friction is a value, not an underflow.
        for (const auto &[name, value] : terms)
            if (value < 0.0)
                out << jointTermProblem(jointLabel(chain, j), QLatin1String(name), value, rule);
    }
    return out;
}

QStringList modelWarnings(const ChainModel &model)
{
    return modelProblems(model, model.chain(), realBodyPrior(model.cadStandard(), model.dof()));
}

} // namespace learnid
