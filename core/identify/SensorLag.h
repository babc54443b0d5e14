#pragma once

#include <Eigen/Core>

namespace learnid {

/// The torques a sensor with a first-order lag of time constant `lag` [s] was given, from its
/// readings (n x N, one column per sample; estimator.torqueSensorLag). The lag, sampled as
/// y_k = y_k-1 + a (x_k - y_k-1) with a = 1 - exp(-Ts / lag) (exact for x held over each
/// sample), is undone exactly: x_k = y_k-1 + (y_k - y_k-1) / a; sample 0 is kept (the lag is
/// taken to start settled). lag 0 returns the readings. Noise on the readings grows by
/// sqrt(1 + 2 (1 - a) / a^2) at the sample rate; the law's filter, far below it, takes it out.
Eigen::MatrixXd withoutSensorLag(const Eigen::MatrixXd &readings, double samplePeriod, double lag);

} // namespace learnid
