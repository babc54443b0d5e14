// Issue-14 benchmark, identification from recorded logs of real robots (../shared/data): the
// KUKA LWR4+ (identify from runs 1 + 2, validate on run 3; and from run 3, validate on run 1)
// and the DFKI double pendulum (identify from trajectories 00-02, validate on 03). Per joint the
// RMS of predicted minus measured torque and its ratio to the measured torque's RMS; overall
// sqrt(sum e^2 / sum tau^2) and the mean of the joint ratios; the starting model, the other
// toolchain's model and learnid's computed by the same code in the same run. Then the CPU time
// of identifying the KUKA's runs. Prints Markdown.
//   learnid-bench-realdata [--rho R] [--share S] [--stride K] [--velocity-from-q]
#include "BenchSupport.h"

#include "identify/LogFit.h"
#include "identify/UniformLog.h"
#include "io/RobotLogCsv.h"
#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/Plausibility.h"
#include "model/UrdfChain.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <cstdio>
#include <cstring>
#include <string>

#ifndef LEARNID_SHARED_DATA
#error "bench/CMakeLists.txt defines LEARNID_SHARED_DATA"
#endif

namespace learnid::bench {
namespace {

struct Options
{
    LogFilterSettings filter;
    LogFitSettings fit;
    JointTerms terms;
    ResampleOptions resample;
};

QString data(const char *file)
{
    return QStringLiteral(LEARNID_SHARED_DATA "/") + QString::fromLatin1(file);
}

FilteredLog loadLog(const QString &path, int joints, const LogColumns &columns, const Options &o)
{
    ResampleOptions resample = o.resample;
    resample.fitBandwidth = o.filter.rho; // the default gap follows the filter, as identify's
    return filterLog(resampleUniform(readRobotLogFile(path, joints, columns), resample), o.filter);
}

struct Model
{
    const char *name;
    Eigen::VectorXd pi;
};

void printComparison(const ChainModel &model, const std::vector<Model> &models,
                     const FilteredLog &validation)
{
    std::vector<TorqueFigures> figures;
    for (const Model &m : models)
        figures.push_back(torqueFigures(model, m.pi, validation));
    std::printf("| joint | RMS measured [N m] |");
    for (const Model &m : models)
        std::printf(" %s: RMS error [N m] (ratio) |", m.name);
    std::printf("\n|---|---|");
    for (size_t i = 0; i < models.size(); ++i)
        std::printf("---|");
    std::printf("\n");
    for (int j = 0; j < model.dof(); ++j) {
        std::printf("| %d | %.3f |", j + 1, figures.front().rmsMeasured[j]);
        for (const TorqueFigures &f : figures)
            std::printf(" %.3f (%.1f %%) |", f.rmsError[j], 100.0 * f.ratio(j));
        std::printf("\n");
    }
    std::printf("| overall sqrt(sum e^2 / sum tau^2) | |");
    for (const TorqueFigures &f : figures)
        std::printf(" **%.2f %%** |", 100.0 * f.overall);
    std::printf("\n| mean of the joint ratios | |");
    for (const TorqueFigures &f : figures)
        std::printf(" %.1f %% |", 100.0 * f.meanRatio);
    std::printf("\n\n");
}

// Per link the plausibility rule of docs/robots.md §6: smallest principal moment about the
// centre of mass against the CAD link's smallest, (I1 + I2) / I3, the centre of mass in the
// link's bounding volume; then joint terms strictly between 0 and 1e-6.
void printPlausibility(const ChainModel &model, const std::vector<Model> &models)
{
    const int n = model.dof();
    const Eigen::VectorXd prior = realBodyPrior(model.cadStandard(), n);
    const auto volumes = linkVolumes(model.chain(), prior);
    std::vector<std::vector<LinkPlausibility>> verdicts;
    for (const Model &m : models)
        verdicts.push_back(checkPlausibility(m.pi, prior, n, volumes));
    std::printf("| link | volume |");
    for (const Model &m : models)
        std::printf(" %s: I_min / CAD's, (I1+I2)/I3, CoM |", m.name);
    std::printf("\n|---|---|");
    for (size_t i = 0; i < models.size(); ++i)
        std::printf("---|");
    std::printf("\n");
    for (int l = 0; l < n; ++l) {
        const auto &e = volumes[size_t(l)];
        std::printf("| %d | %s |", l + 1,
                    !e                                    ? "none"
                    : e->source == VolumeSource::Geometry ? "geometry"
                                                          : "CAD inertia x2");
        for (const auto &v : verdicts) {
            const LinkPlausibility &p = v[size_t(l)];
            std::printf(" %s %.2g, %.3g, %s |", p.plausible ? "ok" : "**no**",
                        p.cadSmallestMoment > 0 ? p.moments[0] / p.cadSmallestMoment : 0.0,
                        p.triangleRatio, p.hasVolume ? (p.volumeOk ? "in" : "out") : "-");
        }
        std::printf("\n");
    }
    std::printf("| terms in (0, 1e-6) | |");
    for (const Model &m : models)
        std::printf(" %zu |", tinyJointTerms(m.pi, model.nonnegativeStandard()).size());
    std::printf("\n\n");
}

void printFit(const ChainModel &model, const LogFit &fit)
{
    std::printf("Fit: %lld samples, %d of %d standard-parameter directions determined "
                "(condition %.3g), %zu of %d base parameters mostly undetermined (kept near the "
                "CAD model); consistent fit %s.\n\n",
                static_cast<long long>(fit.samples), fit.rank, model.standardCount(), fit.condition,
                fit.undetermined().size(), fit.baseCount,
                fit.converged ? "converged" : "stopped at its step limit");
    std::printf("Plausible fit: %s.\n\n", qPrintable(fit.solverReport));
}

// FloBaRoID's published model: its URDF's inertia, <dynamics damping> as viscous friction
// and <dynamics friction> as a torque offset (what the code that wrote it stored there,
// ../shared/data/kuka-lwr4/SOURCE.md), no Coulomb friction.
Eigen::VectorXd flobaroidStandard(const ChainModel &model, const SerialChain &identified)
{
    Eigen::VectorXd pi = model.standardOf(identified);
    const JointTerms &t = model.jointTerms();
    const int n = model.dof();
    for (int j = 0; j < n; ++j) {
        Eigen::Index at = 10 * n + Eigen::Index(j) * t.count() + (t.armature ? 1 : 0);
        at += t.viscous ? 1 : 0;
        if (t.coulomb)
            pi[at++] = 0.0;
        if (t.offset)
            pi[at] = identified.joints[size_t(j)].friction;
    }
    return pi;
}

void kuka(const Options &o)
{
    const SerialChain cad = readUrdfChain(data("kuka-lwr4/kuka_lwr4.urdf"));
    const SerialChain published = readUrdfChain(data("kuka-lwr4/kuka_lwr4_identified.urdf"));
    const ChainModel model(cad, o.terms, QStringLiteral("kuka-lwr4"));
    std::vector<FilteredLog> runs;
    for (const char *f : {"kuka-lwr4/measurements_1.csv", "kuka-lwr4/measurements_2.csv",
                          "kuka-lwr4/measurements_3.csv"})
        runs.push_back(loadLog(data(f), 7, {}, o));
    const Eigen::VectorXd flobaroid = flobaroidStandard(model, published);

    std::printf("### KUKA LWR4+: identified from runs 1 + 2, validated on run 3\n\n");
    const LogFit fit12 = fitLogs(model, {runs[0], runs[1]}, o.fit);
    printFit(model, fit12);
    printComparison(
        model,
        {{"CAD URDF", model.cadStandard()}, {"FloBaRoID", flobaroid}, {"learnid", fit12.standard}},
        runs[2]);
    printPlausibility(
        model,
        {{"CAD URDF", model.cadStandard()}, {"FloBaRoID", flobaroid}, {"learnid", fit12.standard}});
    std::printf("### KUKA LWR4+: identified from run 3, validated on run 1\n\n");
    const LogFit fit3 = fitLogs(model, {runs[2]}, o.fit);
    printFit(model, fit3);
    printComparison(
        model,
        {{"CAD URDF", model.cadStandard()}, {"FloBaRoID", flobaroid}, {"learnid", fit3.standard}},
        runs[0]);
    printPlausibility(
        model,
        {{"CAD URDF", model.cadStandard()}, {"FloBaRoID", flobaroid}, {"learnid", fit3.standard}});

    // CPU time: read, resample, filter and fit runs 1 + 2 (median of 5).
    std::vector<double> cpu;
    for (int i = 0; i < 5; ++i) {
        const double start = cpuSeconds();
        const LogFit f = fitLogs(model,
                                 {loadLog(data("kuka-lwr4/measurements_1.csv"), 7, {}, o),
                                  loadLog(data("kuka-lwr4/measurements_2.csv"), 7, {}, o)},
                                 o.fit);
        cpu.push_back(cpuSeconds() - start);
        if (!f.standard.allFinite())
            std::printf("fit not finite\n");
    }
    std::printf("CPU time to identify the KUKA from runs 1 + 2 (read, resample, filter, fit, "
                "consistent): **%.3f s** (median of 5)\n\n",
                median(cpu));
}

void pendulum(Options o)
{
    o.resample.useNominalTimes = false; // its time stamps are the truth (UniformLog.h)
    const SerialChain lab = readUrdfChain(QStringLiteral(":/robots/double-pendulum.urdf"));
    const ChainModel model(lab, o.terms, QStringLiteral("double-pendulum"));
    const LogColumns columns =
        parseLogColumns(QStringLiteral("t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1"));
    std::vector<FilteredLog> training;
    for (const char *f : {"double-pendulum/trajectory_00.csv", "double-pendulum/trajectory_01.csv",
                          "double-pendulum/trajectory_02.csv"})
        training.push_back(loadLog(data(f), 2, columns, o));
    const FilteredLog validation =
        loadLog(data("double-pendulum/trajectory_03.csv"), 2, columns, o);
    std::printf("### Double pendulum: identified from trajectories 00-02, validated on 03\n\n");
    const LogFit fit = fitLogs(model, training, o.fit);
    printFit(model, fit);
    printComparison(model, {{"lab's model 3.0", model.cadStandard()}, {"learnid", fit.standard}},
                    validation);
    printPlausibility(model, {{"lab's model 3.0", model.cadStandard()}, {"learnid", fit.standard}});
}

} // namespace
} // namespace learnid::bench

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    using namespace learnid;
    bench::Options o;
    o.terms.offset = true;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool value = i + 1 < argc;
        if (a == "--rho" && value)
            o.filter.rho = std::atof(argv[++i]);
        else if (a == "--share" && value)
            o.fit.priorShare = std::atof(argv[++i]);
        else if (a == "--stride" && value)
            o.filter.stride = std::atoi(argv[++i]);
        else if (a == "--velocity-from-q")
            o.filter.velocity = LogFilterSettings::Velocity::FromPositions;
        else if (a == "--nominal-times")
            o.resample.useNominalTimes = true;
        else if (a == "--armature")
            o.terms.armature = true;
        else if (a == "--coulomb-velocity" && value)
            o.terms.coulombVelocity = std::atof(argv[++i]);
        else if (a == "--unweighted")
            o.fit.weighted = false;
        else if (a == "--inconsistent")
            o.fit.consistent = false;
        else if (a == "--geometric-share" && value)
            o.fit.geometricShare = std::atof(argv[++i]);
        else if (a == "--no-volumes")
            o.fit.volumes = false;
        else if (a == "--no-rule")
            o.fit.plausible = false;
        else {
            std::fprintf(
                stderr, "usage: learnid-bench-realdata [--rho R] [--share S] [--geometric-share S] "
                        "[--stride K] [--velocity-from-q] [--nominal-times] [--armature] "
                        "[--coulomb-velocity V] [--unweighted] [--inconsistent] [--no-volumes] "
                        "[--no-rule]\n");
            return 2;
        }
    }
    try {
        std::printf("Filter rho %.3g rad/s, stride %d, %s velocities; prior share %.3g, geometric "
                    "share %.3g, %s, %s%s%s\n\n",
                    o.filter.rho, o.filter.stride,
                    o.filter.velocity == LogFilterSettings::Velocity::FromPositions
                        ? "estimated from q"
                        : "measured (when logged)",
                    o.fit.priorShare, o.fit.geometricShare,
                    o.fit.weighted ? "weighted" : "unweighted",
                    o.fit.consistent ? "consistent" : "least squares",
                    o.fit.volumes ? "" : ", no bounding volumes",
                    o.fit.plausible ? "" : ", no plausibility floor");
        bench::kuka(o);
        bench::pendulum(o);
    } catch (const Error &e) {
        std::fprintf(stderr, "learnid-bench-realdata: %s\n", qPrintable(e.message()));
        return 1;
    }
    return 0;
}
