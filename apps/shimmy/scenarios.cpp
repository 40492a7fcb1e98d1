#include "scenarios.hpp"

#include <stdexcept>

namespace contensou::app {

const std::vector<NamedScenario>& named_scenarios() {
  static const std::vector<NamedScenario> scenarios{
      {"touchdown",
       "unbraked touchdown at 70 m/s: the load builds up over 0.1 s, the tire slides while the "
       "wheel spins up, then rolls",
       {"scenario.braking=false"},
       StabilityPhase::touchdown},
      {"braked-slide",
       "touchdown at 70 m/s, then the anti-skid brake holds slip 0.15 from 0.25 s to 0.95 s: the "
       "tire slides the whole time",
       {},
       StabilityPhase::braked_slide},
      {"large-offset",
       "the braked slide at 58 m/s with the wheel 0.45 m beside the strut axis (a half-fork "
       "gear): the drag's lever on the torsion is long",
       {"structure.offset_m=0.45", "scenario.forward_speed_mps=58"},
       StabilityPhase::braked_slide}};
  return scenarios;
}

std::string scenario_names() {
  std::string s;
  for (const NamedScenario& n : named_scenarios()) s += (s.empty() ? "" : ", ") + n.name;
  return s;
}

const NamedScenario& named_scenario(const std::string& name) {
  for (const NamedScenario& n : named_scenarios())
    if (n.name == name) return n;
  throw std::runtime_error("--scenario " + name + ": unknown scenario (known: " + scenario_names() +
                           ", all)");
}

}  // namespace contensou::app
