// The Bullet back-end: the same shape of physics as the analytic model, determinism across
// thread counts, and per-configuration success rates close to the analytic ground truth.
// Sizes stay small so that the suite also runs quickly under the sanitizers. Built only when
// the pgm_bullet plugin is (its objects register "bullet").

#include "pgm/sim/bullet.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "pgm/sim/agreement.hpp"
#include "sim/sim_support.hpp"

namespace pgm::sim::bullet_tests {
namespace {

using testing::pinned;
using testing::rate;
using testing::shipped;

// PGM_BULLET_TEST_SCALE=k runs k times the rows, to measure agreement more finely.
std::size_t scaled(std::size_t rows) {
  if (const char* factor = std::getenv("PGM_BULLET_TEST_SCALE")) return rows * std::strtoul(factor, nullptr, 10);
  return rows;
}

TEST(bullet_test, same_data_for_any_thread_count) {
  for (const auto* name : {"2-stack", "drop-bowl", "drop-plate"}) {
    simulate_options o;
    o.backend = "bullet";
    o.rows = 37;  // not a multiple of the rows handed out at a time
    o.seed = 11;
    o.threads = 1;
    const auto one = simulate(shipped(name), o);
    for (unsigned threads : {2U, 5U}) {
      o.threads = threads;
      EXPECT_EQ(simulate(shipped(name), o), one) << name << ", " << threads << " threads";
    }
  }
}

struct experiment_result {
  std::vector<double> values;
  std::vector<std::array<double, 7>> poses;
};

experiment_result run_row(bullet_simulator& simulator, const task_definition& task, std::uint64_t seed,
                          std::uint64_t row) {
  experiment_result result{std::vector<double>(task.variables.size()), {}};
  sample_inputs(task, seed, row, result.values);
  random_stream noise(seed, row, stream_purpose::noise);
  simulator.run(std::span<double>(result.values), noise);
  result.poses = simulator.final_poses();
  return result;
}

// A world is reused for every experiment of a thread: an experiment must end the same way,
// to the last bit of every body's pose, whatever ran before it in that world.
TEST(bullet_test, an_experiment_does_not_depend_on_the_ones_before_it) {
  for (const auto* name : {"2-stack", "drop-plate", "drop-bowl", "drop-glass"}) {
    const auto task = shipped(name);
    for (std::uint64_t row : {3U, 4U, 5U}) {
      bullet_simulator fresh(task);
      const auto alone = run_row(fresh, task, 21, row);
      ASSERT_FALSE(alone.poses.empty());
      // Predecessors from another seed: stacks that stand and fall, spheres in and out.
      bullet_simulator used(task);
      std::size_t successes = 0;
      for (std::uint64_t before = 0; before < 12; ++before) {
        successes += static_cast<std::size_t>(run_row(used, task, 99, before).values[task.index(task.success)]);
      }
      EXPECT_GT(successes, 0U) << name;
      EXPECT_LT(successes, 12U) << name;
      const auto after = run_row(used, task, 21, row);
      EXPECT_EQ(after.values, alone.values) << name << " row " << row;
      EXPECT_EQ(after.poses, alone.poses) << name << " row " << row;
      // And the same world gives it again after it.
      (void)run_row(fresh, task, 99, 7);
      EXPECT_EQ(run_row(fresh, task, 21, row).poses, alone.poses) << name << " row " << row;
    }
  }
}

TEST(bullet_test, centred_stack_succeeds_and_offset_cubes_fall) {
  const auto two = shipped("2-stack");
  EXPECT_GT(rate(pinned(two, {{"xOff1", 0.0}, {"yOff1", 0.0}, {"xOff2", 0.0}, {"yOff2", 0.0}}), "bullet", 40), 0.95);
  const auto one = shipped("1-stack");
  std::vector<double> rates;
  for (double x : {0.0, 2.2, 3.0}) {
    rates.push_back(rate(pinned(one, {{"xOff1", x}, {"yOff1", 0.0}, {"dropOff1", 2.0}}), "bullet", 60));
  }
  EXPECT_GT(rates[0], 0.95);
  EXPECT_GT(rates[0], rates[1]);
  EXPECT_GT(rates[1], rates[2]);
  EXPECT_LT(rates[2], 0.1);  // beyond half the cube's width (2.5 cm)
}

TEST(bullet_test, sphere_lands_in_a_glass_and_the_plate_loses_more_than_the_bowl) {
  EXPECT_GT(rate(pinned(shipped("drop-glass"), {{"xOff", 0.0}, {"yOff", 0.0}, {"scalingFactor", 0.8}}), "bullet", 30),
            0.95);
  // Of the spheres that land well within the opening (centre within R - r of the axis), the
  // plate, being shallow, loses more than the bowl.
  auto loss = [](const std::string& name) {
    const auto task = pinned(shipped(name), {{"scalingFactor", 0.6}});
    const auto& p = std::get<dropping_physics>(task.physics);
    const double core = 0.6 * p.diameter_at_scale_1 / 2 - p.sphere_diameter / 2;
    simulate_options o;
    o.backend = "bullet";
    o.rows = scaled(300);
    o.seed = 8;
    o.threads = 2;
    const auto data = simulate(task, o);
    double landed = 0, lost = 0;
    for (std::size_t row = 0; row < data.rows(); ++row) {
      if (std::hypot(data.continuous("xOff").values()[row], data.continuous("yOff").values()[row]) < core) {
        landed += 1;
        lost += 1 - data.discrete("inside").code(row);
      }
    }
    return lost / landed;
  };
  const double plate = loss("drop-plate");
  const double bowl = loss("drop-bowl");
  std::printf("lost after landing within the opening: plate %.3f, bowl %.3f\n", plate, bowl);
  EXPECT_GT(plate, bowl);
}

// The analytic model follows Bullet cell by cell (pgm/sim/agreement.hpp: thirds of the
// offsets' range, and of scalingFactor for dropping), with the constants shipped in tasks/.
// docs/simulators.md shows the full-size table (20,000 Bullet rows); here, smaller sizes.
// Tolerances: the 0.04 on the mean |difference| plus what sampling noise alone adds
// at these sizes (|bias + noise| <= |bias| + |noise|, and the table gives E|noise|); 0.03 on
// the overall rates plus three standard errors.
void expect_agreement(const task_definition& task, std::size_t bullet_rows, double* overall = nullptr) {
  agreement_options o;
  o.reference_rows = bullet_rows;
  o.analytic_rows = 50'000;
  o.seed = 5;
  o.threads = 2;
  const auto table = agreement(task, o);
  std::printf("%s: mean |diff| %.4f (noise alone %.4f), bullet %.3f, analytic %.3f\n", task.name.c_str(),
              table.mean_abs_difference, table.noise_mean_abs_difference, table.reference_rate, table.analytic_rate);
  EXPECT_LT(table.mean_abs_difference, 0.04 + table.noise_mean_abs_difference) << task.name;
  EXPECT_NEAR(table.analytic_rate, table.reference_rate, 0.03 + 3 * table.overall_standard_error) << task.name;
  if (overall) {
    overall[0] = table.reference_rate;
    overall[1] = table.analytic_rate;
  }
}

TEST(bullet_test, analytic_model_agrees_per_cell_for_stacking) {
  expect_agreement(shipped("1-stack"), scaled(1500));
  expect_agreement(shipped("2-stack"), scaled(1500));
}

TEST(bullet_test, analytic_model_agrees_per_cell_for_dropping_and_ranks_the_containers_alike) {
  double plate[2], bowl[2], glass[2];
  expect_agreement(shipped("drop-plate"), scaled(3000), plate);
  expect_agreement(shipped("drop-bowl"), scaled(3000), bowl);
  expect_agreement(shipped("drop-glass"), scaled(3000), glass);
  for (int b = 0; b < 2; ++b) {  // Bullet, then analytic: bowl > plate > glass
    EXPECT_GT(bowl[b], plate[b]);
    EXPECT_GT(plate[b], glass[b]);
  }
}

// Three cubes, with 2-Stack's constants: the centre-of-mass rule over every contact holds
// up in Bullet too.
TEST(bullet_test, three_cubes_fall_as_the_analytic_model_says) {
  const auto three = testing::three_stack();
  expect_agreement(three, scaled(1200));
  // Offsets 1.37, 0.92 and 1.83 cm along x, released gently (0.5 cm, little release noise):
  // every contact of two and then of three cubes carries its load's centre of mass 0.38 cm
  // inside the edge (the largest margin possible), except cubeDown's at the end: the three
  // cubes' centre of mass lies 2.59 cm out, 0.38 cm beyond it, so the third cube brings the
  // stack down.
  auto leaning = pinned(three, {{"xOff1", 1.37},
                                {"xOff2", 0.92},
                                {"xOff3", 1.83},
                                {"yOff1", 0.0},
                                {"yOff2", 0.0},
                                {"yOff3", 0.0},
                                {"dropOff1", 0.5},
                                {"dropOff2", 0.5},
                                {"dropOff3", 0.5}});
  std::get<stacking_physics>(leaning.physics).noise_base = 0.02;
  for (const auto* backend : {"analytic", "bullet"}) {
    EXPECT_GT(rate(leaning, backend, 40, 7, "onTop2"), 0.9) << backend;
    EXPECT_LT(rate(leaning, backend, 40, 7, "onTop3"), 0.1) << backend;
  }
}

}  // namespace
}  // namespace pgm::sim::bullet_tests
