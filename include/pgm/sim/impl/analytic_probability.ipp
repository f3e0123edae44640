#pragma once
// The definitions of pgm/sim/analytic_probability.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/analytic_probability.hpp"

namespace pgm::sim::detail {

PGM_DECL std::pair<std::vector<double>, std::vector<double>> gauss_legendre(std::size_t n) {
  std::vector<double> nodes(n), weights(n);
  for (std::size_t i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (static_cast<double>(i) + 0.75) / (static_cast<double>(n) + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (std::size_t k = 2; k <= n; ++k) {
        const double pk = ((2.0 * static_cast<double>(k) - 1.0) * x * p1 - (static_cast<double>(k) - 1.0) * p0) /
                          static_cast<double>(k);
        p0 = p1;
        p1 = pk;
      }
      if (n == 1) p0 = 1.0;
      derivative = static_cast<double>(n) * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-15) break;
    }
    nodes[i] = x;
    weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
  return {nodes, weights};
}

PGM_DECL restricted restrict_to(const distribution& d, double lo, double hi, std::size_t nodes) {
  restricted r;
  r.dist = &d;
  if (d.continuous()) {
    r.lo = std::max(lo, d.min);
    r.hi = std::min(hi, d.max);
    const double total = d.raw_cdf(d.max) - d.raw_cdf(d.min);
    const double u0 = d.raw_cdf(r.lo);
    const double u1 = d.raw_cdf(r.hi);
    if (!(r.hi > r.lo) || !(u1 > u0)) return r;
    r.mass = (u1 - u0) / total;
    const auto [x, w] = gauss_legendre(nodes);
    for (std::size_t i = 0; i < nodes; ++i) {
      r.values.push_back(d.raw_quantile(u0 + (u1 - u0) * (x[i] + 1) / 2));
      r.weights.push_back(w[i] / 2);
    }
    return r;
  }
  std::size_t total = 0;
  for (double v : d.values) {
    ++total;
    if (v >= lo && v < hi) r.values.push_back(v);
  }
  if (r.values.empty()) return r;
  r.mass = static_cast<double>(r.values.size()) / static_cast<double>(total);
  r.weights.assign(r.values.size(), 1.0 / static_cast<double>(r.values.size()));
  return r;
}

PGM_DECL double noisy_density(const restricted& r, double sd, double t) {
  const auto& d = *r.dist;
  if (d.kind == distribution_kind::normal) {
    const double s = d.scale;
    const double total = std::hypot(s, sd);
    const double m = d.location + (t - d.location) * s * s / (total * total);
    const double tau = s * sd / total;
    const double z = normal_cdf((r.hi - d.location) / s) - normal_cdf((r.lo - d.location) / s);
    return normal_pdf((t - d.location) / total) / total *
           (normal_cdf((r.hi - m) / tau) - normal_cdf((r.lo - m) / tau)) / z;
  }
  if (d.kind == distribution_kind::uniform) {
    return (normal_cdf((t - r.lo) / sd) - normal_cdf((t - r.hi) / sd)) / (r.hi - r.lo);
  }
  double f = 0;
  for (std::size_t i = 0; i < r.values.size(); ++i) f += r.weights[i] * normal_pdf((t - r.values[i]) / sd) / sd;
  return f;
}

PGM_DECL noisy_axis::noisy_axis(const restricted& r, double sd, double lo, double hi, std::size_t intervals)
    : lo_(lo), step_((hi - lo) / static_cast<double>(intervals)), density_(intervals + 1), cumulative_(intervals + 1) {
  for (std::size_t k = 0; k <= intervals; ++k) density_[k] = noisy_density(r, sd, lo + step_ * static_cast<double>(k));
  for (std::size_t k = 1; k <= intervals; ++k) {
    cumulative_[k] = cumulative_[k - 1] + step_ * (density_[k - 1] + density_[k]) / 2;
  }
}

PGM_DECL double noisy_axis::interpolate(const std::vector<double>& table, double t) const {
  const double position = std::clamp((t - lo_) / step_, 0.0, static_cast<double>(table.size() - 1));
  const auto k = std::min(static_cast<std::size_t>(position), table.size() - 2);
  const double fraction = position - static_cast<double>(k);
  return table[k] + fraction * (table[k + 1] - table[k]);
}

PGM_DECL restricted restricted_variable(const task_definition& task, const variable_box& box, const std::string& name,
                                        std::size_t nodes) {
  const auto& d = task.at(name).sampling;
  const auto it = box.find(name);
  const double inf = std::numeric_limits<double>::infinity();
  auto r =
      it == box.end() ? restrict_to(d, -inf, inf, nodes) : restrict_to(d, it->second.first, it->second.second, nodes);
  if (r.mass <= 0) {
    throw data_error("task '" + task.name + "': the interval given for '" + name +
                     "' has probability 0 under its distribution");
  }
  return r;
}

PGM_DECL double stack_axis_integral::level(std::size_t i) {
  const auto& axis = *axes_[i];
  if (i + 1 == axes_.size()) {
    const auto [lo, hi] = standing_offsets(at_, i, half_[i]);
    return hi > lo ? axis.cumulative(hi) - axis.cumulative(lo) : 0.0;
  }
  double total = 0;
  const auto n = axis.intervals();
  for (std::size_t k = 0; k <= n; ++k) {
    const double density = axis.density(k);
    if (density <= 0) continue;
    at_[i] = (i == 0 ? 0.0 : at_[i - 1]) + axis.at(k);
    if (!stage_stands(at_, i, half_[i])) continue;
    total += (k == 0 || k == n ? 0.5 : 1.0) * density * level(i + 1);
  }
  return total * axis.step();
}

PGM_DECL double stacking_probability(const task_definition& task, const stacking_physics& p, std::size_t cubes,
                                     const variable_box& box, const integration_options& o) {
  const double h = p.cube_size / 2 - p.support_margin;
  // Half-width of the supporting faces at each stage (cubes 0..m placed).
  std::vector<double> half(cubes, h - p.tipping_margin_later);
  half[0] = h - p.tipping_margin_first;
  // Release heights matter only through the release noise.
  const std::size_t height_nodes = p.noise_per_cm == 0 ? 1 : o.height_nodes;
  struct axis_inputs {
    restricted x, y, drop;
  };
  std::vector<axis_inputs> inputs;
  for (std::size_t i = 1; i <= cubes; ++i) {
    const auto n = std::to_string(i);
    inputs.push_back({restricted_variable(task, box, "xOff" + n, 16), restricted_variable(task, box, "yOff" + n, 16),
                      restricted_variable(task, box, "dropOff" + n, height_nodes)});
  }
  // Per cube and release-height node: the density of where the cube settles on [-half, half].
  std::vector<std::vector<std::pair<noisy_axis, noisy_axis>>> axes(cubes);
  for (std::size_t i = 0; i < cubes; ++i) {
    const double settle = i == 0 ? p.settle_noise_first : p.settle_noise_later;
    const double edge = half[i];  // the cube's own contact bounds its offset at its stage
    for (double height : inputs[i].drop.values) {
      const double sd = std::hypot(p.noise_base + p.noise_per_cm * height, settle);
      axes[i].emplace_back(noisy_axis(inputs[i].x, sd, -edge, edge, o.stacking_grid),
                           noisy_axis(inputs[i].y, sd, -edge, edge, o.stacking_grid));
    }
  }
  // Sum over every combination of release-height nodes; the axes are independent given them.
  double total = 0;
  std::vector<std::size_t> node(cubes, 0);
  for (;;) {
    double weight = 1;
    std::vector<const noisy_axis*> xs, ys;
    for (std::size_t i = 0; i < cubes; ++i) {
      weight *= inputs[i].drop.weights[node[i]];
      xs.push_back(&axes[i][node[i]].first);
      ys.push_back(&axes[i][node[i]].second);
    }
    total += weight * stack_axis_integral(xs, half)() * stack_axis_integral(ys, half)();
    std::size_t i = 0;
    while (i < cubes && ++node[i] == inputs[i].drop.values.size()) node[i++] = 0;
    if (i == cubes) break;
  }
  return total;
}

PGM_DECL std::vector<std::pair<double, double>> staying_intervals(const container_profile& c, const dropping_physics& p,
                                                                  std::size_t steps) {
  std::vector<std::pair<double, double>> intervals;
  const double end = c.rim_rho() + c.reach();  // beyond, the sphere misses the container
  auto stays = [&](double rho) { return sphere_stays(c, p, rho); };
  auto edge = [&](double lo, double hi) {  // stays(lo) != stays(hi)
    const bool at_lo = stays(lo);
    for (int i = 0; i < 60 && hi - lo > 1e-10; ++i) {
      const double mid = (lo + hi) / 2;
      (stays(mid) == at_lo ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  };
  double previous = 0;
  bool inside = stays(0);
  double start = 0;
  for (std::size_t k = 1; k <= steps; ++k) {
    const double rho = end * static_cast<double>(k) / static_cast<double>(steps);
    if (const bool now = stays(rho); now != inside) {
      const double at = edge(previous, rho);
      if (inside) intervals.emplace_back(start, at);
      start = at;
      inside = now;
    }
    previous = rho;
  }
  if (inside) intervals.emplace_back(start, end);
  return intervals;
}

PGM_DECL double dropping_probability(const task_definition& task, const dropping_physics& p, const variable_box& box,
                                     const integration_options& o) {
  const auto x = restricted_variable(task, box, "xOff", 16);
  const auto y = restricted_variable(task, box, "yOff", 16);
  const auto s = restricted_variable(task, box, "scalingFactor", o.scale_nodes);
  std::vector<container_profile> containers;
  double largest = 0;
  for (double scale : s.values) {
    containers.emplace_back(p, scale);
    largest = std::max(largest, containers.back().rim_rho() + containers.back().reach());
  }
  const double sd = std::hypot(p.landing_noise, p.landing_scatter);
  const noisy_axis ax(x, sd, -largest, largest, o.dropping_grid);
  const noisy_axis ay(y, sd, -largest, largest, o.dropping_grid);
  // Named, not a structured binding: the lambda below captures them (clang before 16 cannot).
  const auto quadrature = gauss_legendre(o.angle_nodes);
  const auto& angles = quadrature.first;
  const auto& angle_weights = quadrature.second;
  // P(landing within `within` of the axis); t = within·sin θ, so the half-chord is within·cos θ.
  auto disc = [&](double within) {
    if (within <= 0) return 0.0;
    double sum = 0;
    for (std::size_t a = 0; a < angles.size(); ++a) {
      const double theta = angles[a] * std::numbers::pi / 2;
      const double t = within * std::sin(theta);
      const double chord = within * std::cos(theta);
      sum += angle_weights[a] * ax.density_at(t) * (ay.cumulative(chord) - ay.cumulative(-chord)) * chord;
    }
    return sum * std::numbers::pi / 2;
  };
  double total = 0;
  for (std::size_t j = 0; j < s.values.size(); ++j) {
    double stays = 0;
    for (const auto& [from, to] : staying_intervals(containers[j], p, o.radial_steps)) stays += disc(to) - disc(from);
    total += s.weights[j] * stays;
  }
  return total;
}

}  // namespace pgm::sim::detail

namespace pgm::sim {

PGM_DECL double analytic_outcome_probability(const task_definition& task, std::string_view outcome,
                                             const variable_box& box, const integration_options& options) {
  for (const auto& [name, interval] : box) {
    if (!task.contains(name) || task.at(name).kind != variable_kind::continuous) {
      throw data_error("task '" + task.name + "' has no continuous variable '" + name + "' to restrict");
    }
    if (!(interval.first < interval.second)) {
      throw data_error("the interval for '" + name + "' is empty");
    }
  }
  if (const auto* s = std::get_if<stacking_physics>(&task.physics)) {
    for (std::size_t i = 1; i <= s->cubes; ++i) {
      if (outcome == "onTop" + std::to_string(i)) return detail::stacking_probability(task, *s, i, box, options);
    }
  } else if (outcome == "inside") {
    return detail::dropping_probability(task, std::get<dropping_physics>(task.physics), box, options);
  }
  throw data_error("task '" + task.name + "' has no outcome '" + std::string(outcome) + "'");
}

}  // namespace pgm::sim
