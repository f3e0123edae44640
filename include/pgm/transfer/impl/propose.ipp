#pragma once
// The definitions of pgm/transfer/propose.hpp: inline in a header-only build, compiled once into libpgm
// under PGM_SEPARATE_COMPILATION (pgm/core/compilation.hpp).

#include "pgm/transfer/propose.hpp"

namespace pgm::detail {

PGM_DECL std::string name_stem(std::string_view name) {
  while (!name.empty() && std::isdigit(static_cast<unsigned char>(name.back()))) name.remove_suffix(1);
  std::string stem(name);
  for (auto& c : stem) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return stem;
}

PGM_DECL std::optional<std::pair<double, double>> value_range(const variable& v) {
  if (v.has_intervals()) return std::pair{v.edges().front(), v.edges().back()};
  std::optional<std::pair<double, double>> range;
  for (std::size_t s = 0; s < v.cardinality(); ++s) {
    const auto m = v.midpoint(index_at<state_index>(s));
    if (!m) return std::nullopt;
    range = range ? std::pair{std::min(range->first, *m), std::max(range->second, *m)} : std::pair{*m, *m};
  }
  return range;
}

PGM_DECL std::optional<std::vector<double>> root_marginal(const network_view& view, const std::string& name) {
  if (!view.network) return std::nullopt;
  const auto& table = view.network->table(name);
  if (!table.parents().empty()) return std::nullopt;
  const auto column = table.column(config_index(0));
  return std::vector<double>(column.begin(), column.end());
}

}  // namespace pgm::detail

namespace pgm {

PGM_DECL correspondence_candidate score_pair(const variable& target, const variable& prior,
                                             const network_view& target_view, const network_view& prior_view) {
  correspondence_candidate c{target.name(), prior.name(), 0, {}};
  double total = 0, weight = 0;
  auto add = [&](double part, double w, std::string reason) {
    total += part * w;
    weight += w;
    c.reasons.push_back(std::move(reason));
  };
  const auto ts = detail::name_stem(target.name()), ps = detail::name_stem(prior.name());
  std::size_t common = 0;
  while (common < std::min(ts.size(), ps.size()) && ts[common] == ps[common]) ++common;
  const double stem =
      ts == ps ? 1.0 : static_cast<double>(common) / static_cast<double>(std::max(ts.size(), ps.size()));
  add(stem, 0.4,
      ts == ps ? "same name stem '" + ts + "'"
               : "name stems '" + ts + "'/'" + ps + "' share " + std::to_string(common) + " letters");

  const auto& tt = target.tags();
  const auto& pt = prior.tags();
  if (!tt.quantity.empty() && !pt.quantity.empty()) {
    const double q = tt.quantity == pt.quantity ? 1.0 : 0.0;
    const double u = tt.unit == pt.unit ? 1.0 : 0.0;
    add(0.75 * q + 0.25 * u, 0.3,
        q != 0.0 ? "same quantity '" + tt.quantity + "'" + (u != 0.0 ? " in " + tt.unit : ", other units")
                 : "other quantities '" + tt.quantity + "'/'" + pt.quantity + "'");
  }
  const auto tr = detail::value_range(target), pr = detail::value_range(prior);
  if (tr && pr) {
    const double overlap = std::max(0.0, std::min(tr->second, pr->second) - std::max(tr->first, pr->first));
    const double span = std::max(tr->second, pr->second) - std::min(tr->first, pr->first);
    const double part = span > 0 ? overlap / span : 1.0;
    add(part, 0.15, "value ranges overlap " + text::format_short(100 * part, 3) + " %");
  } else if (tr.has_value() != pr.has_value()) {
    add(0.0, 0.15, "one is numeric, the other categorical");
  }
  const auto tm = detail::root_marginal(target_view, target.name());
  const auto pm = detail::root_marginal(prior_view, prior.name());
  if (tm && pm) {
    try {
      const auto mapping = map_states(target, prior);
      std::vector<double> moved(pm->size(), 0.0);
      for (std::size_t s = 0; s < mapping.size(); ++s) {
        for (const auto& share : mapping[s]) moved[share.state] += (*tm)[s] * share.weight;
      }
      double tv = 0;
      for (std::size_t s = 0; s < moved.size(); ++s) tv += std::abs(moved[s] - (*pm)[s]);
      tv /= 2;
      add(1 - tv, 0.15, "marginals differ by " + text::format_short(tv, 2) + " in total variation");
    } catch (const model_error&) {
      add(0.0, 0.15, "states cannot be matched");
    }
  }
  c.score = weight > 0 ? total / weight : 0;
  return c;
}

PGM_DECL std::vector<correspondence_candidate> rank_correspondences(const network_view& target,
                                                                    const network_view& prior) {
  std::vector<correspondence_candidate> ranking;
  for (const auto& t : target.structure->variables()) {
    for (const auto& p : prior.structure->variables()) {
      if (t.name() != p.name()) ranking.push_back(score_pair(t, p, target, prior));
    }
  }
  std::stable_sort(ranking.begin(), ranking.end(), [](const auto& a, const auto& b) { return a.score > b.score; });
  return ranking;
}

PGM_DECL correspondence propose_correspondence(const network_view& target, const network_view& prior,
                                               correspondence map, double threshold) {
  auto sinks = [](const network_structure& s) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const variable_id id = index_at<variable_id>(i);
      if (s.graph().children(id).empty() && !s.parents(id).empty()) names.push_back(s.at(id).name());
    }
    return names;
  };
  if (map.transferred.empty()) {
    std::optional<correspondence_candidate> best;
    for (const auto& t : sinks(*target.structure)) {
      for (const auto& p : sinks(*prior.structure)) {
        auto c = t == p ? correspondence_candidate{t, p, 1.0, {}}
                        : score_pair(target.structure->at(t), prior.structure->at(p), target, prior);
        if (!best || c.score > best->score) best = std::move(c);
      }
    }
    if (!best) throw model_error("no outcome (a node with parents and no children) to transfer between the networks");
    map.transferred.emplace(best->target, best->prior);
  }
  for (const auto& [target_node, prior_node] : map.transferred) {
    const auto target_parents = target.structure->parent_variables(target.structure->id(target_node));
    const auto prior_parents = prior.structure->parent_variables(prior.structure->id(prior_node));
    std::vector<correspondence_candidate> pairs;
    for (const auto& t : target_parents) {
      for (const auto& p : prior_parents) {
        if (map.identical_to(t.name()) != p.name()) pairs.push_back(score_pair(t, p, target, prior));
      }
    }
    std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.score > b.score; });
    std::vector<std::string> used_prior;
    for (const auto& c : pairs) {
      if (c.score < threshold || map.related.contains(c.target)) continue;
      if (std::find(used_prior.begin(), used_prior.end(), c.prior) != used_prior.end()) continue;
      map.related.emplace(c.target, c.prior);
      used_prior.push_back(c.prior);
    }
  }
  return map;
}

}  // namespace pgm
