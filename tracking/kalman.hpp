#pragma once
// `kalman`: Kalman-filter pose predictor.
//
// Position: a linear Kalman filter per axis on [p, v] (constant velocity, CV) or [p, v, a]
// (constant acceleration, CA); the highest derivative is driven by continuous white noise of
// spectral density q (white-noise-acceleration / white-noise-jerk model), discretised exactly
// for the actual dt: Q_ij = q dt^(2m+1-i-j) / ((2m+1-i-j) (m-i)! (m-j)!), m = order - 1.
//
// Orientation: a multiplicative (error-state) EKF. The nominal orientation is a unit quaternion
// q; the filter state is [dtheta, w] or [dtheta, w, alpha] where dtheta is a world-frame
// rotation-vector error (q_true = exp(dtheta) q), w the world-frame angular velocity and alpha
// the angular acceleration. Propagation: q <- exp(w dt + alpha dt^2/2) q, w <- w + alpha dt;
// the error obeys d(dtheta)/dt = w x dtheta + dw, so its transition block is the rotation
// exp(w dt) (coupling to w and alpha as in the linear model). Measurement: the residual is the
// rotation vector log(q_meas q^-1) (shorter arc, so q/-q flips are no residual), H = [I 0 ..].
// After the update the error is folded into q and reset to zero with the reset Jacobian
// G = I + [dtheta/2]x. Quaternion components are never filtered.
//
// Robustness: the covariance update uses the Joseph form and is symmetrised after every step;
// when a Cholesky factorisation fails (round-off with extreme noise settings) the eigenvalues
// are clamped to a small positive floor. dt = 0 (duplicate timestamp) is a measurement update
// without propagation; older samples are ignored; a gap longer than maxGap restarts the filter
// from the new sample (an extrapolation over seconds is worthless and its covariance huge).
#include "tracking/noise_adaptation.hpp"
#include "tracking/predictor.hpp"

#include <Eigen/Dense>

#include <variant>

namespace strata::tracking {

enum class MotionModel { ConstantVelocity, ConstantAcceleration };

struct KalmanOptions {
    MotionModel positionModel = MotionModel::ConstantVelocity;
    MotionModel orientationModel = MotionModel::ConstantVelocity;
    // Measurement noise (standard deviations), the synthetic sensor's defaults: sensor-fused HMD
    // orientation jitters by hundredths of a degree, optical position by a fraction of a mm.
    double positionSigma = 0.2e-3;                          // m
    double orientationSigma = 0.02 * 0.017453292519943295;  // rad
    // Process noise spectral densities of the highest modelled derivative. Tuned on 60 s of the
    // synthetic head motion (seed 1, 120 Hz, 50 ms latency; strata track --synthetic 60) by a
    // sweep over half-decades; the mean error is flat within ~10 % over a factor 3. Units:
    // CV: acceleration noise (m^2/s^3, rad^2/s^3); CA: jerk noise (m^2/s^5, rad^2/s^5).
    double positionProcessCV = 0.1;
    double positionProcessCA = 10.0;
    double orientationProcessCV = 3.0;
    double orientationProcessCA = 1000.0;
    // Initial standard deviations of the derivatives (position: m/s, m/s^2; rad/s, rad/s^2).
    double initialVelocitySigma = 2.0, initialAccelerationSigma = 20.0;
    double initialAngularVelocitySigma = 6.0, initialAngularAccelerationSigma = 60.0;
    double maxGap = 1.0;  // s; a longer silence restarts the filter
    // Adaptive noise (tracking/noise_adaptation.hpp): the measurement sigmas are estimated from
    // the stream and the process densities scaled by innovation covariance matching, within
    // [minScale, maxScale] of the values above, which are then only the starting point.
    bool adaptive = false;
    ProcessNoiseAdaptation processAdaptation;
    // Extrapolation with the CA models: the estimated acceleration decays over the horizon with
    // this correlation time (Singer 1970) instead of being held; 0 holds it. A head's
    // acceleration reverses within every turn (speeding up, then braking), so holding it over
    // 50 ms overshoots each turn's end and lags its start.
    double accelerationDecay = 0.0;  // s
};

// The noise levels a Kalman predictor is using now (adapted ones when adaptive).
struct KalmanNoiseLevels {
    double orientationSigma = 0.0, positionSigma = 0.0;        // rad, m (measurement)
    double orientationProcess = 0.0, positionProcess = 0.0;    // spectral densities in use
    double orientationScale = 1.0, positionScale = 1.0;        // ... relative to the options'
    double orientationNis = 0.0, positionNis = 0.0;            // mean NIS / dimension (1 = matched)
};

// Position filter: three axes with the same model, noise and initial covariance have the same
// covariance, so the 3*Order filter is exactly three Order-state filters sharing one
// Order x Order covariance and gain (P_full = P kron I3). State column a = axis a, row k = k-th
// derivative.
template <int Order>
class AxisKalman {
public:
    using Mat = Eigen::Matrix<double, Order, Order>;
    using State = Eigen::Matrix<double, Order, 3>;

    void init(const Eigen::Vector3d& first, double firstSigma, double d1Sigma, double d2Sigma);
    static constexpr int order() { return Order; }
    static Mat transition(double dt);
    void propagate(double dt, double spectralDensity);
    // Also sets nis, the innovation's normalised square r^T S^-1 r (prior covariance).
    void correct(const Eigen::Vector3d& measurement, double sigma);
    void keepSymmetricPositiveDefinite();
    Eigen::Vector3d value() const { return x.row(0).transpose(); }
    Eigen::Vector3d derivative(int k) const { return x.row(k).transpose(); }

    State x = State::Zero();
    Mat P = Mat::Identity();
    double nis = 0.0;
};

// Kalman filter over 3-D kinematic blocks [x, x', (x'')] (Order 2 or 3 blocks of 3 values);
// the first block is measured directly. Fixed-size so Eigen unrolls the small products and
// nothing is allocated per update (a 9x9 dynamic-size version measured ~7 us per update).
template <int Order>
class KinematicKalman {
public:
    static constexpr int N = 3 * Order;
    using Mat = Eigen::Matrix<double, N, N>;
    using Vec = Eigen::Matrix<double, N, 1>;

    void init(const Eigen::Vector3d& first, double firstSigma, double d1Sigma, double d2Sigma);
    static constexpr int order() { return Order; }
    // Linear kinematic transition for dt: block (i, j) = dt^(j-i)/(j-i)! I for j >= i.
    static Mat transition(double dt);
    // x <- F x (when propagateState), P <- F P F^T + Q(dt; q).
    void propagate(const Mat& F, double dt, double spectralDensity, bool propagateState);
    // Measurement of the first block with residual r and variance sigma^2 per axis; returns dx
    // and sets nis = r^T S^-1 r.
    Vec correct(const Eigen::Vector3d& residual, double sigma);
    // P <- G P G^T (error-state reset); G must be the identity outside its top-left 3x3 block.
    void transform(const Mat& G);
    // Symmetrises, and when Cholesky fails clamps the eigenvalues to a positive floor. The
    // steps above only symmetrise; the (costlier) check runs once per update.
    void keepSymmetricPositiveDefinite();

    Vec x = Vec::Zero();
    Mat P = Mat::Identity();
    double nis = 0.0;
};

class KalmanPredictor final : public Predictor {
public:
    explicit KalmanPredictor(const KalmanOptions& options = {}, std::string name = "kalman")
        : options_(options), name_(std::move(name)) {}
    void update(const PoseSample& sample) override;
    PoseSample predict(double time) const override;
    std::string_view name() const override { return name_; }
    void reset() override;
    std::unique_ptr<Predictor> clone() const override { return std::make_unique<KalmanPredictor>(*this); }

    const KalmanOptions& options() const { return options_; }
    // For tests: the filters' covariances (6x6 or 9x9), the nominal orientation and the
    // angular velocity.
    Eigen::MatrixXd positionCovariance() const;
    Eigen::MatrixXd orientationCovariance() const;
    const Eigen::Quaterniond& orientation() const { return q_; }
    Eigen::Vector3d angularVelocity() const;
    // The noise levels in use (the options' when not adaptive).
    KalmanNoiseLevels noiseLevels() const;
    // One line of them for panels and logs: "sigma 0.020 deg 0.20 mm, process x1.3 / x0.8".
    std::string describeState() const override;

private:
    void start(const PoseSample& sample);
    double orientationSigma() const;
    double positionSigma() const;
    KalmanOptions options_;
    std::string name_;
    template <int Order> void updateOrientation(KinematicKalman<Order>& f, const PoseSample& s, double dt);
    // Position state [p, v, (a)]; orientation state [dtheta (0 between updates), w, (alpha)].
    std::variant<AxisKalman<2>, AxisKalman<3>> position_;
    std::variant<KinematicKalman<2>, KinematicKalman<3>> orientation_;
    Eigen::Quaterniond q_ = Eigen::Quaterniond::Identity();
    double lastT_ = 0.0;
    bool have_ = false;
    // Adaptive mode only.
    MeasurementNoiseEstimator measurementNoise_;
    ProcessNoiseScale positionScale_{options_.processAdaptation}, orientationScale_{options_.processAdaptation};
};

}  // namespace strata::tracking
