// exact_resultants for a patch, and the explicit instantiation for double (exact_resultants.hpp).
#include "contensou/friction/exact_resultants.hpp"

namespace contensou {

ExactResult<double> exact_resultants(const ContactPatch& patch, const Kinematics<double>& k,
                                     const ExactOptions& options) {
  return exact_resultants(make_exact_model(patch), k, options);
}

template ExactResult<double> exact_resultants<double>(const ExactModel<double>&,
                                                      const Kinematics<double>&,
                                                      const ExactOptions&);

}  // namespace contensou
