#include "contensou/identification/exact_law_cache.hpp"

namespace contensou {

ExactLawCache::ExactLawCache(double radius_m, std::optional<ExactModel<double>> profile,
                             double tolerance)
    : radius_m_(radius_m), tolerance_(tolerance), profile_(std::move(profile)) {}

const std::vector<ExactLaw>& ExactLawCache::laws(bool slip_speed, const StopRequest& stop) const {
  const int which = slip_speed ? 1 : 0;
  std::call_once(once_[which], [this, which, &stop] {
    // Any f_s != f_k builds the falling table; the fit sets f_s = 1, f_k = 1 - beta, w_s.
    std::optional<SlipSpeedFriction<double>> slip;
    if (which == 1) slip = SlipSpeedFriction<double>{1.0, 0.5, 1.0, 1.0};
    ExactLawOptions options{tolerance_};
    options.stop = stop;
    std::vector<ExactLaw> laws;  // moved in when complete: an interrupted build leaves none
    if (profile_) {
      ExactModel<double> m = *profile_;
      m.slip_speed = slip;
      m.friction = 1.0;
      m.friction_scale = 1.0;
      laws.push_back(make_exact_law(m, options));
      laws_[which] = std::move(laws);
      return;
    }
    for (const std::vector<double>& c : {std::vector<double>{1.0}, std::vector<double>{1.0, 1.0},
                                         std::vector<double>{1.0, 0.0, 1.0}}) {
      ContactPatch patch;
      patch.radius_m = radius_m_;
      patch.reference_pressure_pa = 1.0;
      patch.friction = 1.0;
      patch.profile.shape = ChebyshevShape{c};
      patch.slip_speed_friction = slip;
      laws.push_back(make_exact_law(make_exact_model(patch), options));
    }
    laws_[which] = std::move(laws);
  });
  return laws_[which];
}

}  // namespace contensou
