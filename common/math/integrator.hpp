// Fixed-step numerical integrators for y' = f(t, y) (seed 2.5): forward Euler, RK4 and
// Adams-Bashforth 2/3/4 with an RK4 starter. Fixed-size Eigen vectors: a step never allocates.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cmath>

#include "common/math/integration_method.hpp"

namespace fedsim {

/// Integrates an N-element state. The method can be changed at run time; Adams-Bashforth keeps a
/// history of past derivatives which restart() clears (call it after a reset, a reposition or
/// any jump in the state). Until the history is long enough the AB methods take RK4 steps (the
/// starter), so an AB-k run is accurate to order k from its first step; a change of step length
/// also restarts the history because the AB coefficients assume equal steps.
template <int N>
class Integrator {
 public:
  using Vector = Eigen::Matrix<double, N, 1>;

  explicit Integrator(IntegrationMethod method = IntegrationMethod::kRk4) : method_(method) {
    history_.fill(Vector::Zero());
  }

  IntegrationMethod method() const { return method_; }
  void set_method(IntegrationMethod method) {
    method_ = method;
    restart();
  }
  /// Forgets the derivative history: the next AB steps are RK4 starter steps.
  void restart() { history_size_ = 0; }
  /// Number of past derivatives held (at most 4).
  int history_size() const { return history_size_; }

  /// Advances y from t to t + h; derivative(t, y) returns dy/dt as a Vector.
  template <class Derivative>
  void step(double t, double h, Vector& y, Derivative&& derivative) {
    const Vector f0 = derivative(t, y);
    step_from(t, h, y, f0, derivative);
  }

  /// As step(), with f0 = derivative(t, y) already known (saves one evaluation).
  template <class Derivative>
  void step_from(double t, double h, Vector& y, const Vector& f0, Derivative&& derivative) {
    if (history_size_ > 0 && std::abs(h - history_h_) > 1e-12 * std::abs(h)) restart();
    push_history(f0);
    history_h_ = h;
    const int needed = history_needed();
    if (method_ == IntegrationMethod::kEuler) {
      y += h * f0;
    } else if (needed > 0 && history_size_ >= needed) {
      adams_bashforth(h, y);
    } else {
      runge_kutta_4(t, h, y, f0, derivative);  // RK4, or the starter of an AB method
    }
  }

  /// One frame of length frame_dt in `substeps` equal steps (the step is an integer fraction
  /// of the frame period).
  template <class Derivative>
  void step_frame(double t, double frame_dt, int substeps, Vector& y, Derivative&& derivative) {
    const double h = frame_dt / static_cast<double>(substeps);
    for (int i = 0; i < substeps; ++i) step(t + h * static_cast<double>(i), h, y, derivative);
  }

 private:
  int history_needed() const {
    switch (method_) {
      case IntegrationMethod::kAb2: return 2;
      case IntegrationMethod::kAb3: return 3;
      case IntegrationMethod::kAb4: return 4;
      default: return 0;
    }
  }

  void push_history(const Vector& f) {
    for (int i = static_cast<int>(history_.size()) - 1; i > 0; --i) history_[i] = history_[i - 1];
    history_[0] = f;
    if (history_size_ < static_cast<int>(history_.size())) ++history_size_;
  }

  void adams_bashforth(double h, Vector& y) const {
    const std::array<Vector, 4>& f = history_;  // f[0] = f_n, f[1] = f_(n-1), ...
    switch (method_) {
      case IntegrationMethod::kAb2:
        y += h * (1.5 * f[0] - 0.5 * f[1]);
        break;
      case IntegrationMethod::kAb3:
        y += (h / 12.0) * (23.0 * f[0] - 16.0 * f[1] + 5.0 * f[2]);
        break;
      default:
        y += (h / 24.0) * (55.0 * f[0] - 59.0 * f[1] + 37.0 * f[2] - 9.0 * f[3]);
        break;
    }
  }

  template <class Derivative>
  static void runge_kutta_4(double t, double h, Vector& y, const Vector& k1,
                            Derivative& derivative) {
    const double half = 0.5 * h;
    const Vector k2 = derivative(t + half, Vector(y + half * k1));
    const Vector k3 = derivative(t + half, Vector(y + half * k2));
    const Vector k4 = derivative(t + h, Vector(y + h * k3));
    y += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }

  IntegrationMethod method_;
  std::array<Vector, 4> history_;
  int history_size_ = 0;
  double history_h_ = 0.0;
};

}  // namespace fedsim
