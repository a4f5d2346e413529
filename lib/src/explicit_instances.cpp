// Instantiates every class template of lib/ for float and double under the strict
// firmware flags (see lib/CMakeLists.txt), so a warning in any of them fails the build
// even before a test or a firmware image uses it.
#include "aloft/aloft.hpp"

namespace aloft {
template class InertiaTensor<float>;
template class InertiaTensor<double>;
template class PrincipalFrame<float>;
template class PrincipalFrame<double>;
template void principal_rk4_step<float>(const EulerCoefficients<float>&, PrincipalState<float>&,
                                        const float&);
template void principal_rk4_step<double>(const EulerCoefficients<double>&, PrincipalState<double>&,
                                         const double&);
template float lane_deviation_angle<float>(const LaneVec3<float>&, const LaneVec3<float>&);
template double lane_deviation_angle<double>(const LaneVec3<double>&, const LaneVec3<double>&);
template class BatchFlight<float>;
template class BatchFlight<double>;
template class Rk4Integrator<float>;
template class Rk4Integrator<double>;
template class SplittingIntegrator<float>;
template class SplittingIntegrator<double>;
template class DeviationStats<float>;
template class DeviationStats<double>;
template class OnboardCheck<float, 8>;
template class OnboardCheck<double, 8>;
template class LeverArmFit<float>;
template class LeverArmFit<double>;
template class SampleHistory<float, 32>;
template class SampleHistory<double, 32>;
template class ReleaseDetector<float, 32>;
template class ReleaseDetector<double, 32>;
template class ReleaseDetector<float, 32, GyrostatTorqueTest<float, 32>>;
template class ReleaseDetector<double, 32, GyrostatTorqueTest<double, 32>>;
template class OnboardPipeline<float, 8>;
template class OnboardPipeline<double, 8>;
template class OnboardPipeline<float, 8, RotorSupport::none>;
template class icm42688p::FifoDecoder<float>;
template class icm42688p::FifoDecoder<double>;
template class icm42688p::Icm42688pDriver<float>;
template class icm42688p::Icm42688pDriver<double>;
}  // namespace aloft
