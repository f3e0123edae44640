#pragma once
// The definitions of pgm/sim/calibrate.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/sim/calibrate.hpp"

namespace pgm::sim::detail {

PGM_DECL std::vector<fitted_constant> fitted_constants(const task_definition& task) {
  std::vector<fitted_constant> result;
  if (const auto* s = std::get_if<stacking_physics>(&task.physics)) {
    const double edge = s->cube_size / 2 - s->support_margin;
    auto stack = [](double stacking_physics::*member) {
      return [member](physics_parameters& p) -> double& { return std::get<stacking_physics>(p).*member; };
    };
    result.push_back({"tipping_margin/first", 0.0, 0.5 * edge, stack(&stacking_physics::tipping_margin_first)});
    result.push_back({"settle_noise/first", 0.0, 0.25 * edge, stack(&stacking_physics::settle_noise_first)});
    if (s->cubes > 1) {
      result.push_back({"tipping_margin/later", 0.0, 0.5 * edge, stack(&stacking_physics::tipping_margin_later)});
      result.push_back({"settle_noise/later", 0.0, 0.25 * edge, stack(&stacking_physics::settle_noise_later)});
    }
  } else {
    auto drop = [](double dropping_physics::*member) {
      return [member](physics_parameters& p) -> double& { return std::get<dropping_physics>(p).*member; };
    };
    const auto& d = std::get<dropping_physics>(task.physics);
    result.push_back({"restitution", 0.0, 1.0, drop(&dropping_physics::impact_restitution)});
    result.push_back({"tangential", 0.0, 1.0, drop(&dropping_physics::impact_tangential)});
    result.push_back({"scatter", 0.0, d.sphere_diameter / 2, drop(&dropping_physics::landing_scatter)});
    result.push_back({"rim_clearance", -d.sphere_diameter, d.sphere_diameter, drop(&dropping_physics::rim_clearance)});
  }
  return result;
}

PGM_DECL std::vector<std::pair<double, double>> normal_nodes(double a, double b, const std::vector<double>& x,
                                                             const std::vector<double>& w) {
  std::vector<std::pair<double, double>> nodes;
  const double u0 = normal_cdf(a), u1 = normal_cdf(b);
  if (!(u1 > u0)) return nodes;
  for (std::size_t i = 0; i < x.size(); ++i) {
    nodes.emplace_back(normal_quantile(u0 + (u1 - u0) * (x[i] + 1) / 2), (u1 - u0) * w[i] / 2);
  }
  return nodes;
}

PGM_DECL stacking_likelihood::stacking_likelihood(const task_definition& task, const dataset& data,
                                                  std::uint64_t seed) {
  const auto& p = std::get<stacking_physics>(task.physics);
  const std::size_t n = p.cubes;
  cubes_ = n;
  std::vector<std::span<const double>> xs, ys, drops;
  std::vector<const discrete_column*> outcomes;
  for (std::size_t i = 1; i <= n; ++i) {
    const auto k = std::to_string(i);
    xs.push_back(data.continuous("xOff" + k).values());
    ys.push_back(data.continuous("yOff" + k).values());
    drops.push_back(data.continuous("dropOff" + k).values());
    outcomes.push_back(&data.discrete("onTop" + k));
  }
  for (std::size_t row = 0; row < data.rows(); ++row) {
    random_stream noise(seed, row, stream_purpose::noise);
    row_data r;
    for (std::size_t i = 0; i < n; ++i) {
      const double sd = p.noise_base + p.noise_per_cm * drops[i][row];
      r.x.push_back(xs[i][row] + sd * noise.normal());
      r.y.push_back(ys[i][row] + sd * noise.normal());
    }
    while (r.standing < n && outcomes[r.standing]->code(row) == 1) ++r.standing;
    rows_.push_back(std::move(r));
  }
  std::tie(x_, w_) = gauss_legendre(16);
}

PGM_DECL double stacking_likelihood::operator()(const task_definition& task) const {
  const auto& p = std::get<stacking_physics>(task.physics);
  const double h = p.cube_size / 2 - p.support_margin;
  std::vector<double> half(cubes_, h - p.tipping_margin_later);
  half[0] = h - p.tipping_margin_first;
  std::vector<double> settle(cubes_, p.settle_noise_later);
  settle[0] = p.settle_noise_first;
  double total = 0;
  for (const auto& r : rows_) {
    // P(the first m stages stand) per axis; the outcome is "m stood, the next did not".
    auto stood = [&](std::size_t m) {
      if (m == 0) return 1.0;
      return axis(r.x, m, half, settle) * axis(r.y, m, half, settle);
    };
    const double p_stood = stood(r.standing);
    total += clamped_log(r.standing == cubes_ ? p_stood : p_stood - stood(r.standing + 1));
  }
  return total;
}

PGM_DECL double stacking_likelihood::axis(const std::vector<double>& t, std::size_t m, const std::vector<double>& half,
                                          const std::vector<double>& settle) const {
  std::vector<double> at(m);  // settled positions relative to cubeDown
  return level(0, m, t, half, settle, at);
}

PGM_DECL double stacking_likelihood::level(std::size_t i, std::size_t m, const std::vector<double>& t,
                                           const std::vector<double>& half, const std::vector<double>& settle,
                                           std::vector<double>& at) const {
  const double base = i == 0 ? 0.0 : at[i - 1];
  if (i + 1 == m) {
    // The last cube: its offset must lie in an interval.
    const auto [lo, hi] = standing_offsets(at, i, half[i]);
    if (!(hi > lo)) return 0.0;
    if (settle[i] <= 0) return t[i] > lo && t[i] < hi ? 1.0 : 0.0;
    return normal_cdf((hi - t[i]) / settle[i]) - normal_cdf((lo - t[i]) / settle[i]);
  }
  if (settle[i] <= 0) {
    at[i] = base + t[i];
    return stage_stands(at, i, half[i]) ? level(i + 1, m, t, half, settle, at) : 0.0;
  }
  double total = 0;
  const double a = (-half[i] - t[i]) / settle[i], b = (half[i] - t[i]) / settle[i];
  for (const auto& [z, weight] : normal_nodes(std::max(a, -8.0), std::min(b, 8.0), x_, w_)) {
    at[i] = base + t[i] + settle[i] * z;
    if (stage_stands(at, i, half[i])) total += weight * level(i + 1, m, t, half, settle, at);
  }
  return total;
}

PGM_DECL dropping_likelihood::dropping_likelihood(const task_definition& task, const dataset& data,
                                                  std::uint64_t seed) {
  const auto& p = std::get<dropping_physics>(task.physics);
  const auto xs = data.continuous("xOff").values();
  const auto ys = data.continuous("yOff").values();
  const auto scales = data.continuous("scalingFactor").values();
  const auto& inside = data.discrete("inside");
  for (std::size_t row = 0; row < data.rows(); ++row) {
    random_stream noise(seed, row, stream_purpose::noise);
    const double x = xs[row] + p.landing_noise * noise.normal();
    const double y = ys[row] + p.landing_noise * noise.normal();
    rows_.push_back({x, y, container_profile(p, scales[row]), inside.code(row) == 1});
  }
  const auto [x, w] = gauss_legendre(8);
  nodes_ = normal_nodes(-8, 8, x, w);
}

PGM_DECL double dropping_likelihood::operator()(const task_definition& task) const {
  const auto& p = std::get<dropping_physics>(task.physics);
  double total = 0;
  for (const auto& r : rows_) {
    double stays = 0;
    if (p.landing_scatter <= 0) {
      stays = sphere_stays(r.container, p, std::hypot(r.x, r.y)) ? 1.0 : 0.0;
    } else {
      for (const auto& [zx, wx] : nodes_) {
        for (const auto& [zy, wy] : nodes_) {
          const double rho = std::hypot(r.x + p.landing_scatter * zx, r.y + p.landing_scatter * zy);
          if (sphere_stays(r.container, p, rho)) stays += wx * wy;
        }
      }
    }
    total += clamped_log(r.inside ? stays : 1 - stays);
  }
  return total;
}

PGM_DECL double rounded(double value, int digits) {
  if (value == 0 || !std::isfinite(value)) return value;
  const double scale = std::pow(10.0, digits - 1 - static_cast<int>(std::floor(std::log10(std::abs(value)))));
  return std::round(value * scale) / scale;
}

}  // namespace pgm::sim::detail

namespace pgm::sim {

PGM_DECL calibration_result calibrate(const task_definition& task, const dataset& data, std::uint64_t seed,
                                      const calibration_options& options) {
  if (data.rows() == 0) throw data_error("calibrate needs at least one experiment (rows must be positive)");
  const auto start = std::chrono::steady_clock::now();
  calibration_result result;
  result.task = task;
  result.rows = data.rows();
  result.seed = seed;
  result.reference = options.reference;
  std::function<double(const task_definition&)> log_likelihood;
  if (std::holds_alternative<stacking_physics>(task.physics)) {
    log_likelihood = detail::stacking_likelihood(task, data, seed);
  } else {
    log_likelihood = detail::dropping_likelihood(task, data, seed);
  }
  auto constants = detail::fitted_constants(task);
  for (const auto& c : constants) result.constants.push_back({c.name, c.at(result.task.physics), 0});
  result.log_likelihood_before = log_likelihood(result.task);
  double best = result.log_likelihood_before;
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    const double at_start = best;
    for (const auto& c : constants) {
      auto& value = c.at(result.task.physics);
      const double kept = value;
      auto minus = [&](double v) {
        value = v;
        return -log_likelihood(result.task);
      };
      std::uintmax_t iterations = 40;
      const auto found = boost::math::tools::brent_find_minima(minus, c.lo, c.hi, 12, iterations);
      // Brent's search may end on a worse local minimum than where it started: keep the better.
      value = detail::rounded(found.first, 4);
      if (const double ll = log_likelihood(result.task); ll > best) {
        best = ll;
      } else {
        value = kept;
      }
    }
    if (best - at_start < 0.01) break;
  }
  for (std::size_t i = 0; i < constants.size(); ++i) result.constants[i].after = constants[i].at(result.task.physics);
  result.log_likelihood_after = best;
  result.fit_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

PGM_DECL calibration_result calibrate(const task_definition& task, const calibration_options& options) {
  if (options.rows == 0) throw data_error("calibrate needs at least one experiment (rows must be positive)");
  if (options.rows > max_calibration_rows) {
    throw data_error(std::to_string(options.rows) + " experiments are more than " +
                     std::to_string(max_calibration_rows) +
                     ", pgm's limit of a calibration (its fit keeps every experiment in memory; docs/limits.md)");
  }
  simulate_options o;
  o.backend = options.reference;
  o.rows = options.rows;
  o.seed = options.seed;
  o.threads = options.threads;
  o.progress = options.progress;
  const auto start = std::chrono::steady_clock::now();
  const auto data = simulate(task, o);
  const double simulated = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto result = calibrate(task, data, options.seed, options);
  result.simulate_seconds = simulated;
  return result;
}

PGM_DECL std::string calibrated_task_text(std::string_view original, const calibration_result& result) {
  auto doc = nlohmann::ordered_json::parse(original);
  auto& physics = doc["physics"];
  nlohmann::ordered_json analytic = nlohmann::ordered_json::object();
  const auto previous = physics.contains("analytic") ? physics["analytic"] : nlohmann::ordered_json::object();
  analytic["note"] = "fitted by pgm calibrate to " + std::to_string(result.rows) + " " + result.reference +
                     " experiments (seed " + std::to_string(result.seed) + "): log-likelihood " +
                     pgm::text::format_double(detail::rounded(result.log_likelihood_before, 6)) + " before, " +
                     pgm::text::format_double(detail::rounded(result.log_likelihood_after, 6)) + " after";
  for (const auto& [key, value] : previous.items()) {
    if (key != "note") analytic[key] = value;
  }
  for (const auto& c : result.constants) {
    const auto slash = c.name.find('/');
    if (slash == std::string::npos) {
      analytic[c.name] = c.after;
    } else {
      analytic[c.name.substr(0, slash)][c.name.substr(slash + 1)] = c.after;
    }
  }
  physics["analytic"] = analytic;
  return doc.dump(2) + "\n";
}

}  // namespace pgm::sim
