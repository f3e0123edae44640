// A user's structure learner: the Chow-Liu tree, the spanning tree of largest mutual information
// between the columns (Chow & Liu 1968), its edges pointing away from the first column. An edge
// of less information than `min_information` (nats) is left out, which gives a forest.

#include <cmath>
#include <cstddef>
#include <pgm/learn/structure_learner_registry.hpp>
#include <vector>

namespace {

/// The mutual information of two columns, in nats, over the rows where both are present.
double mutual_information(const pgm::discrete_column& x, const pgm::discrete_column& y) {
  const std::size_t rx = x.var().cardinality(), ry = y.var().cardinality();
  std::vector<double> joint(rx * ry, 0.0), px(rx, 0.0), py(ry, 0.0);
  double rows = 0;
  for (std::size_t row = 0; row < x.size(); ++row) {
    if (x.is_missing(row) || y.is_missing(row)) continue;
    joint[x.code(row) * ry + y.code(row)] += 1;
    px[x.code(row)] += 1;
    py[y.code(row)] += 1;
    rows += 1;
  }
  double information = 0;
  for (std::size_t i = 0; i < rx; ++i) {
    for (std::size_t j = 0; j < ry; ++j) {
      const double n = joint[i * ry + j];
      if (n > 0) information += n / rows * std::log(n * rows / (px[i] * py[j]));
    }
  }
  return information;
}

class chow_liu_learner {
 public:
  static std::vector<pgm::option_declaration> options() {
    return {
        pgm::number_option("min_information", 0.0, "the least mutual information of an edge, in nats").at_least(0.0)};
  }
  explicit chow_liu_learner(const pgm::option_values& options) : min_information_(options.number("min_information")) {}

  pgm::structure_result learn(const pgm::structure_problem& problem) const {
    // Prim's algorithm from the first column: each step joins the column of most information
    // with one already in the tree, which becomes its parent.
    const std::size_t n = problem.columns.size();
    std::vector<bool> in_tree(n, false);
    std::vector<double> best(n, -1.0);
    std::vector<std::size_t> parent(n, 0);
    std::vector<pgm::named_edge> edges;
    for (std::size_t joined = 0, next = 0; joined < n; ++joined) {
      in_tree[next] = true;
      if (joined > 0 && best[next] >= min_information_) {
        edges.push_back({problem.names[parent[next]], problem.names[next]});
      }
      for (std::size_t k = 0; k < n; ++k) {
        if (in_tree[k]) continue;
        const double information = mutual_information(*problem.columns[next], *problem.columns[k]);
        if (information > best[k]) {
          best[k] = information;
          parent[k] = next;
        }
      }
      for (std::size_t k = 0; k < n; ++k) {
        if (!in_tree[k] && (in_tree[next] || best[k] > best[next])) next = k;
      }
    }
    return pgm::dag_result(problem.names, edges);
  }

 private:
  double min_information_;
};

const pgm::register_structure_learner<chow_liu_learner> registered("chow-liu",
                                                                   "the spanning tree of most mutual information");

}  // namespace
