#include "contensou/identification/identify.hpp"

#include <algorithm>

namespace contensou {

namespace {

// The index in `data` of a point of a subset of it (points keep their line; synthetic data
// without lines are matched by value).
int original_index(const MeasuredData& data, const MeasuredPoint& p) {
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const MeasuredPoint& q = data.points[i];
    if (q.line == p.line && q.kinematics.vx == p.kinematics.vx &&
        q.kinematics.vy == p.kinematics.vy && q.kinematics.omega == p.kinematics.omega)
      return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

Identification identify(const MeasuredData& data, const IdentifyOptions& options) {
  Identification r;
  r.fitted = data;
  if (options.leave_out_outliers) {
    // One gross error at a time (the most extreme of each channel), refitting in between, so
    // that a large one does not make its neighbours look wrong; the fractional law's fit is
    // enough, since a smooth misfit cancels in the rule.
    FitReport current = fit_fractional_law(data, options.fit);
    for (int round = 0; round < 50; ++round) {
      const std::vector<Outlier> found = find_outliers(r.fitted, current.prediction);
      if (found.empty()) break;
      std::vector<Outlier> worst;  // the most extreme of each channel (found is sorted)
      for (const Outlier& o : found)
        if (std::none_of(worst.begin(), worst.end(),
                         [&](const Outlier& w) { return w.channel == o.channel; }))
          worst.push_back(o);
      const std::size_t before = r.outliers.size();
      for (Outlier o : worst) {
        o.point = original_index(data, r.fitted.points[o.point]);
        if (o.point >= 0) r.outliers.push_back(o);
      }
      if (r.outliers.size() == before) break;
      r.fitted = without_outliers(data, r.outliers);
      current = fit_fractional_law(r.fitted, options.fit);
    }
    if (r.outliers.empty() && !options.loop) {
      r.fit = current;
      return r;
    }
  }
  if (options.loop) {
    r.loop = close_the_loop(r.fitted, options.fit, *options.loop);
    r.fit = r.loop->base;
  } else {
    r.fit = fit_fractional_law(r.fitted, options.fit);
  }
  return r;
}

}  // namespace contensou
