// (Internal, not installed) The exact model and laws of a fit's profile, built once for all the
// fits of one identify(): the loop on the rows and again on each resample would otherwise each
// build the same tables (the slip-speed law's is the costly one). Options that carry shared
// laws were given them by LawSharing::share from their own radius and profile, so a fit made
// with them builds exactly the laws it would build alone.
#pragma once

#include <memory>
#include <optional>

#include "contensou/friction/exact_model.hpp"
#include "contensou/identification/exact_law_cache.hpp"
#include "contensou/identification/fit.hpp"

namespace contensou::detail {

struct SharedLaws {
  std::optional<ExactModel<double>> profile_model;  ///< the given profile's (none: parametric)
  std::shared_ptr<ExactLawCache> laws;              ///< built on first use, thread-safe
};

struct LawSharing {
  /// Gives `o` the shared laws of its radius and profile (none built yet); validates the
  /// radius and profile as base_spec_for does.
  static void share(IdentificationOptions& o);
  /// The shared laws of `o`, or nullptr.
  static const SharedLaws* of(const IdentificationOptions& o) { return o.shared_laws_.get(); }
};

}  // namespace contensou::detail
