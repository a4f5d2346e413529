#include "diagnose/3_fit/fit_setup.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

}  // namespace

const FlightOwnParameters* FitSetup::own() const {
  const FlightOwnParameters& own = describe(effect).flight_own;
  return own.count > 0 && base.empty() ? &own : nullptr;
}

int FitSetup::local_count() const { return 3 + (own() != nullptr ? own()->count : 0); }

int FitSetup::shared_count(int model_count) const {
  return own() != nullptr && model_count > 0 ? own()->shared_count : model_count;
}

Eigen::VectorXd FitSetup::block_theta(const Eigen::VectorXd& shared, const Eigen::VectorXd& local) const {
  const FlightOwnParameters* o = own();
  if (o == nullptr) return shared;
  return o->theta_of(shared.head(o->shared_count), local.tail(o->count));
}

void residuals_of(const FlightData& data, const std::vector<Vec3>& readings, Eigen::VectorXd& r) {
  const Flight& flight = *data.flight;
  const std::size_t n = flight.size();
  r.resize(static_cast<Eigen::Index>(3 * n));
  const char* const mask = data.mask.data();
  const char* const usable = flight.usable.data();
  const Vec3* const predicted = readings.data();
  const Vec3* const read = flight.omega.data();
  const Vec3 weight = data.inverse_sigma;
  double* out = r.data();
  for (std::size_t k = 0; k < n; ++k, out += 3) {
    if (!mask[k] || !usable[k]) {
      out[0] = out[1] = out[2] = 0.0;
    } else {
      for (int i = 0; i < 3; ++i) out[i] = (predicted[k](i) - read[k](i)) * weight(i);
    }
  }
}

}  // namespace aloft::host::diagnose
