#include "tracking/kalman.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace strata::tracking {
namespace {

constexpr double kFactorial[] = {1.0, 1.0, 2.0, 6.0};

// Discrete process noise of white noise on the highest of Order derivatives (density q):
// Q_ij = q dt^(2m+1-i-j) / ((2m+1-i-j) (m-i)! (m-j)!), m = Order - 1.
template <int Order>
double processNoise(int i, int j, double dt, double q) {
    constexpr int m = Order - 1;
    const int p = 2 * m + 1 - i - j;
    return q * std::pow(dt, p) / (p * kFactorial[m - i] * kFactorial[m - j]);
}

// Symmetrise; if Cholesky fails (round-off with extreme noise ratios), clamp the eigenvalues to
// a floor relative to the largest so the matrix is positive definite again, keeping its shape.
template <typename M>
void makeSymmetricPositiveDefinite(M& P) {
    P = (0.5 * (P + P.transpose())).eval();
    Eigen::LLT<M> llt(P);
    if (llt.info() == Eigen::Success) return;
    Eigen::SelfAdjointEigenSolver<M> es(P);
    auto lambda = es.eigenvalues().eval();
    const double floor = std::max(1e-300, 1e-15 * lambda.cwiseAbs().maxCoeff());
    lambda = lambda.cwiseMax(floor);
    P = es.eigenvectors() * lambda.asDiagonal() * es.eigenvectors().transpose();
    P = (0.5 * (P + P.transpose())).eval();
}

}  // namespace

template <int Order>
void AxisKalman<Order>::init(const Eigen::Vector3d& first, double firstSigma, double d1Sigma, double d2Sigma) {
    x.setZero();
    x.row(0) = first.transpose();
    const double sig[3] = {firstSigma, d1Sigma, d2Sigma};
    P.setZero();
    for (int k = 0; k < Order; ++k) P(k, k) = sig[k] * sig[k];
}

template <int Order>
typename AxisKalman<Order>::Mat AxisKalman<Order>::transition(double dt) {
    Mat F = Mat::Identity();
    for (int i = 0; i < Order; ++i)
        for (int j = i + 1; j < Order; ++j) F(i, j) = std::pow(dt, j - i) / kFactorial[j - i];
    return F;
}

template <int Order>
void AxisKalman<Order>::propagate(double dt, double q) {
    const Mat F = transition(dt);
    x = (F * x).eval();
    Mat Q;
    for (int i = 0; i < Order; ++i)
        for (int j = 0; j < Order; ++j) Q(i, j) = processNoise<Order>(i, j, dt, q);
    P = (F * P * F.transpose()).eval() + Q;
}

template <int Order>
void AxisKalman<Order>::correct(const Eigen::Vector3d& z, double sigma) {
    const double r = sigma * sigma;
    const double s = P(0, 0) + r;
    const Eigen::Matrix<double, Order, 1> K = P.col(0) / s;
    const Eigen::RowVector3d residual = z.transpose() - x.row(0);
    nis = residual.squaredNorm() / s;
    x += K * residual;
    Mat A = Mat::Identity();
    A.col(0) -= K;
    P = (A * P * A.transpose()).eval() + r * K * K.transpose();  // Joseph form
}

template <int Order>
void AxisKalman<Order>::keepSymmetricPositiveDefinite() {
    makeSymmetricPositiveDefinite(P);
}

template class AxisKalman<2>;
template class AxisKalman<3>;

template <int Order>
void KinematicKalman<Order>::init(const Eigen::Vector3d& first, double firstSigma, double d1Sigma, double d2Sigma) {
    x.setZero();
    x.template head<3>() = first;
    P.setZero();
    const double sig[3] = {firstSigma, d1Sigma, d2Sigma};
    for (int b = 0; b < Order; ++b) P.template block<3, 3>(3 * b, 3 * b).diagonal().setConstant(sig[b] * sig[b]);
}

template <int Order>
typename KinematicKalman<Order>::Mat KinematicKalman<Order>::transition(double dt) {
    Mat F = Mat::Identity();
    for (int i = 0; i < Order; ++i)
        for (int j = i + 1; j < Order; ++j)
            F.template block<3, 3>(3 * i, 3 * j).diagonal().setConstant(std::pow(dt, j - i) / kFactorial[j - i]);
    return F;
}

template <int Order>
void KinematicKalman<Order>::propagate(const Mat& F, double dt, double q, bool propagateState) {
    if (propagateState) x = F.lazyProduct(x).eval();
    Mat Q = Mat::Zero();
    for (int i = 0; i < Order; ++i)
        for (int j = 0; j < Order; ++j)
            Q.template block<3, 3>(3 * i, 3 * j).diagonal().setConstant(processNoise<Order>(i, j, dt, q));
    // lazyProduct: coefficient-wise products, which beat Eigen's blocked GEMM at 9x9.
    const Mat FP = F.lazyProduct(P);
    P = FP.lazyProduct(F.transpose()) + Q;
}

template <int Order>
typename KinematicKalman<Order>::Vec KinematicKalman<Order>::correct(const Eigen::Vector3d& residual, double sigma) {
    const double r = sigma * sigma;
    // H = [I 0 ...]: S = P00 + R, K = P(:, 0:3) S^-1. S is 3x3 SPD (P is kept SPD and r >= 0);
    // the closed-form 3x3 inverse is exact enough at any scale because S is well conditioned
    // relative to its own magnitude (P00 and r scale together).
    const Eigen::Matrix3d S = P.template topLeftCorner<3, 3>() + r * Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d Sinv = S.inverse();
    const Eigen::Matrix<double, N, 3> K = P.template leftCols<3>().lazyProduct(Sinv);
    const Vec dx = K.lazyProduct(residual);
    nis = residual.dot(Sinv * residual);
    x += dx;
    // Joseph form (I-KH) P (I-KH)^T + K R K^T: stays symmetric positive semi-definite for any
    // gain, unlike (I-KH) P, which round-off can push indefinite when R << P.
    // A = I - K H differs from I only in its first three columns, so A P = P - K P(0:3, :) and
    // (A P) A^T = AP - AP(:, 0:3) K^T: the same product, at a third of the dense cost.
    const Mat AP = P - K.lazyProduct(P.template topRows<3>());
    P = AP - AP.template leftCols<3>().lazyProduct(K.transpose()) + r * K.lazyProduct(K.transpose());
    return dx;
}

template <int Order>
void KinematicKalman<Order>::transform(const Mat& G) {
    // G is the identity outside its top-left 3x3 block: only three rows and columns change.
    const Eigen::Matrix3d g = G.template topLeftCorner<3, 3>();
    P.template topRows<3>() = g.lazyProduct(P.template topRows<3>()).eval();
    P.template leftCols<3>() = P.template leftCols<3>().lazyProduct(g.transpose()).eval();
}

template <int Order>
void KinematicKalman<Order>::keepSymmetricPositiveDefinite() {
    makeSymmetricPositiveDefinite(P);
}

template class KinematicKalman<2>;
template class KinematicKalman<3>;

void KalmanPredictor::reset() {
    have_ = false;
    // The learnt noise belongs to the sensor and the motion: a restart after a gap keeps it,
    // only a reset forgets it.
    measurementNoise_.reset();
    positionScale_.reset();
    orientationScale_.reset();
}

// Bounded to 1e-3..1e3 times the configured sigma: a noise-free stream would otherwise drive
// the estimate to zero and the gain to exactly one.
double KalmanPredictor::orientationSigma() const {
    const double o = options_.orientationSigma;
    if (!options_.adaptive) return o;
    return std::clamp(measurementNoise_.orientationSigma(o), 1e-3 * o, 1e3 * o);
}

double KalmanPredictor::positionSigma() const {
    const double o = options_.positionSigma;
    if (!options_.adaptive) return o;
    return std::clamp(measurementNoise_.positionSigma(o), 1e-3 * o, 1e3 * o);
}

void KalmanPredictor::start(const PoseSample& s) {
    const auto& o = options_;
    auto initPosition = [&](auto& f) {
        f.init(s.p, positionSigma(), o.initialVelocitySigma, o.initialAccelerationSigma);
    };
    auto initOrientation = [&](auto& f) {
        f.init(Eigen::Vector3d::Zero(), orientationSigma(), o.initialAngularVelocitySigma,
               o.initialAngularAccelerationSigma);
    };
    if (o.positionModel == MotionModel::ConstantAcceleration)
        position_.emplace<AxisKalman<3>>();
    else
        position_.emplace<AxisKalman<2>>();
    if (o.orientationModel == MotionModel::ConstantAcceleration)
        orientation_.emplace<KinematicKalman<3>>();
    else
        orientation_.emplace<KinematicKalman<2>>();
    std::visit(initPosition, position_);
    std::visit(initOrientation, orientation_);
    q_ = safeNormalized(s.q);
    lastT_ = s.t;
    have_ = true;
}

template <int Order>
void KalmanPredictor::updateOrientation(KinematicKalman<Order>& f, const PoseSample& s, double dt) {
    using Filter = KinematicKalman<Order>;
    const auto& o = options_;
    if (dt > 0.0) {
        // Move the nominal quaternion, then the derivative states linearly; the error block is
        // transported by the rotation over the step (d dtheta/dt = w x dtheta + dw).
        const Eigen::Vector3d w = f.x.template segment<3>(3);
        Eigen::Vector3d a = Eigen::Vector3d::Zero();
        if constexpr (Order == 3) a = f.x.template segment<3>(6);
        const Eigen::Quaterniond step = quatExp(w * dt + 0.5 * dt * dt * a);
        q_ = safeNormalized(step * q_);
        typename Filter::Mat F = Filter::transition(dt);
        F.template topLeftCorner<3, 3>() = step.toRotationMatrix();
        f.x.template segment<3>(3) += a * dt;
        const double q = (Order == 3 ? o.orientationProcessCA : o.orientationProcessCV) * orientationScale_.scale();
        f.propagate(F, dt, q, false);
    }
    const Eigen::Vector3d residual = worldDelta(q_, s.q);  // log(q_meas q^-1), shorter arc
    f.x.template head<3>().setZero();
    const typename Filter::Vec dx = f.correct(residual, orientationSigma());
    if (o.adaptive) orientationScale_.add(f.nis, 3, dt);
    const Eigen::Vector3d dtheta = dx.template head<3>();
    q_ = safeNormalized(quatExp(dtheta) * q_);
    f.x.template head<3>().setZero();
    // Error reset: the new error relative to the moved nominal is G dtheta, G = I + [dtheta/2]x.
    typename Filter::Mat G = Filter::Mat::Identity();
    G.template topLeftCorner<3, 3>() += 0.5 * skew(dtheta);
    f.transform(G);
    f.keepSymmetricPositiveDefinite();
}

void KalmanPredictor::update(const PoseSample& s) {
    if (!s.p.allFinite() || !s.q.coeffs().allFinite()) return;  // never let NaN into the state
    if (options_.adaptive) measurementNoise_.add(s);
    if (!have_) {
        start(s);
        return;
    }
    const double dt = s.t - lastT_;
    if (dt < 0.0) return;
    if (dt > options_.maxGap) {
        start(s);
        return;
    }
    const auto& o = options_;
    std::visit(
        [&](auto& f) {
            constexpr int order = std::decay_t<decltype(f)>::order();
            const double q = (order == 3 ? o.positionProcessCA : o.positionProcessCV) * positionScale_.scale();
            if (dt > 0.0) f.propagate(dt, q);
            f.correct(s.p, positionSigma());
            if (o.adaptive) positionScale_.add(f.nis, 3, dt);
            f.keepSymmetricPositiveDefinite();
        },
        position_);
    std::visit([&](auto& f) { updateOrientation(f, s, dt); }, orientation_);
    if (dt > 0.0) lastT_ = s.t;
}

PoseSample KalmanPredictor::predict(double time) const {
    if (!have_) return PoseSample{time, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()};
    const double tau = time - lastT_;
    // Weight of the acceleration over the horizon: tau^2/2 when it is held (CA), and
    // T^2 (e^(-tau/T) - 1 + tau/T) when it decays with correlation time T (Singer 1970), which
    // tends to tau^2/2 as T grows.
    const double T = options_.accelerationDecay;
    const double ka = T > 0.0 ? T * T * (std::exp(-tau / T) - 1.0 + tau / T) : 0.5 * tau * tau;
    const Eigen::Vector3d p = std::visit(
        [&](const auto& f) {
            Eigen::Vector3d r = f.value() + tau * f.derivative(1);
            if constexpr (std::decay_t<decltype(f)>::order() == 3) r += ka * f.derivative(2);
            return r;
        },
        position_);
    const Eigen::Vector3d phi = std::visit(
        [&](const auto& f) {
            Eigen::Vector3d r = tau * f.x.template segment<3>(3);
            if constexpr (std::decay_t<decltype(f)>::order() == 3) r += ka * f.x.template segment<3>(6);
            return r;
        },
        orientation_);
    return PoseSample{time, p, safeNormalized(quatExp(phi) * q_)};
}

KalmanNoiseLevels KalmanPredictor::noiseLevels() const {
    const auto& o = options_;
    const bool ca = o.orientationModel == MotionModel::ConstantAcceleration;
    const bool caP = o.positionModel == MotionModel::ConstantAcceleration;
    KalmanNoiseLevels n;
    n.orientationSigma = orientationSigma();
    n.positionSigma = positionSigma();
    n.orientationScale = orientationScale_.scale();
    n.positionScale = positionScale_.scale();
    n.orientationProcess = (ca ? o.orientationProcessCA : o.orientationProcessCV) * n.orientationScale;
    n.positionProcess = (caP ? o.positionProcessCA : o.positionProcessCV) * n.positionScale;
    n.orientationNis = std::max(0.0, orientationScale_.meanNis()) / 3.0;
    n.positionNis = std::max(0.0, positionScale_.meanNis()) / 3.0;
    return n;
}

std::string KalmanPredictor::describeState() const {
    if (!options_.adaptive) return {};
    const KalmanNoiseLevels n = noiseLevels();
    char buf[128];
    std::snprintf(buf, sizeof buf, "noise %.4f deg %.2f mm, process x%.2g rot x%.2g pos", radToDeg(n.orientationSigma),
                  n.positionSigma * 1e3, n.orientationScale, n.positionScale);
    return buf;
}

Eigen::MatrixXd KalmanPredictor::positionCovariance() const {
    // Expanded to the full 3*Order covariance (axis-major blocks like the orientation filter's).
    return std::visit(
        [](const auto& f) {
            const int n = f.order();
            Eigen::MatrixXd full = Eigen::MatrixXd::Zero(3 * n, 3 * n);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) full.block(3 * i, 3 * j, 3, 3).diagonal().setConstant(f.P(i, j));
            return full;
        },
        position_);
}

Eigen::MatrixXd KalmanPredictor::orientationCovariance() const {
    return std::visit([](const auto& f) { return Eigen::MatrixXd(f.P); }, orientation_);
}

Eigen::Vector3d KalmanPredictor::angularVelocity() const {
    return std::visit([](const auto& f) { return Eigen::Vector3d(f.x.template segment<3>(3)); }, orientation_);
}

}  // namespace strata::tracking
