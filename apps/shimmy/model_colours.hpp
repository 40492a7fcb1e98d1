// One colour per contact model in every picture of the shimmy demo.
#pragma once

#include "contensou/gear/landing_gear.hpp"

namespace contensou::app {

inline const char* model_colour(ContactModel m) {
  switch (m) {
    case ContactModel::coupled:
      return "#d62728";  // red
    case ContactModel::decoupled:
      return "#1f77b4";  // blue
    case ContactModel::von_schlippe:
      return "#2ca02c";  // green
  }
  return "#000000";
}

}  // namespace contensou::app
