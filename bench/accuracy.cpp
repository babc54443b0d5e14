// Accuracy benchmark: for each learning law and measurement condition, the RMS over seeds of the
// maximum relative parameter error after k learning trials, and the mean max tracking error of
// the trial run with estimate k. Runs the real session on the simulated paper scenario.
// Prints Markdown. Usage: learnid-bench-accuracy [seeds] [trials]
#include "BenchSupport.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace learnid;

namespace {

struct Condition
{
    const char *name;
    qint64 counts;
    double noise;
};

} // namespace

int main(int argc, char **argv)
{
    const int seeds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 8;
    const int trials = argc > 2 ? std::max(1, std::atoi(argv[2])) : 6;
    const Condition conditions[] = {{"noise free", 0, 0.0},
                                    {"2^20 counts, 1 % torque noise", qint64(1) << 20, 0.01},
                                    {"2^16 counts, 1 % torque noise", qint64(1) << 16, 0.01}};

    std::printf("Max relative parameter error [%%] after k learning trials, RMS over %d seeds\n\n",
                seeds);
    std::printf("| law | measurement |");
    for (int k = 1; k <= trials; ++k)
        std::printf(" k=%d |", k);
    std::printf("\n|---|---|");
    for (int k = 1; k <= trials; ++k)
        std::printf("---|");
    std::printf("\n");

    std::vector<std::vector<double>> tracking; // per row: mean max tracking error per trial
    std::vector<std::string> rowNames;
    for (const char *law : {"paper", "improved"}) {
        for (const Condition &c : conditions) {
            std::vector<double> sumSq(size_t(trials), 0.0), track(size_t(trials), 0.0);
            for (int seed = 1; seed <= seeds; ++seed) {
                Scenario s;
                s.law = QString::fromLatin1(law);
                s.simulation.encoderCounts = c.counts;
                s.simulation.torqueNoise = c.noise;
                s.simulation.seed = quint64(seed);
                auto session = bench::makeSession(s);
                if (!session->runTrials(trials)) {
                    std::fprintf(stderr, "%s / %s / seed %d: %s\n", law, c.name, seed,
                                 qPrintable(session->history().constLast().message));
                    return 1;
                }
                for (int k = 1; k <= trials; ++k) {
                    const Eigen::VectorXd rel =
                        (session->estimates().at(k) - s.simulation.trueParameters)
                            .cwiseQuotient(s.simulation.trueParameters);
                    sumSq[size_t(k - 1)] += std::pow(100.0 * rel.cwiseAbs().maxCoeff(), 2);
                    track[size_t(k - 1)] +=
                        session->history().at(k - 1).maxTrackingErrorDeg.maxCoeff() / seeds;
                }
            }
            std::printf("| %s | %s |", law, c.name);
            for (int k = 0; k < trials; ++k)
                std::printf(" %.3f |", std::sqrt(sumSq[size_t(k)] / seeds));
            std::printf("\n");
            tracking.push_back(track);
            rowNames.push_back(std::string(law) + " | " + c.name);
        }
    }

    std::printf("\nMax tracking error [deg] of the trial run with estimate k (k = 0: phi_0), "
                "mean over %d seeds\n\n| law | measurement |",
                seeds);
    for (int k = 0; k < trials; ++k)
        std::printf(" k=%d |", k);
    std::printf("\n|---|---|");
    for (int k = 0; k < trials; ++k)
        std::printf("---|");
    std::printf("\n");
    for (size_t r = 0; r < tracking.size(); ++r) {
        std::printf("| %s |", rowNames[r].c_str());
        for (double v : tracking[r])
            std::printf(" %.5f |", v);
        std::printf("\n");
    }
    return 0;
}
