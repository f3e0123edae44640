#pragma once
/// \file
/// What the conformance kits share: a component's choice as a GoogleTest name, and the cases of
/// every registered component, each as the caller describes it or with the kit's defaults.

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

namespace pgm::testing {

/// `choice` as a test name: every character but a letter or a digit an underscore
/// ("bp[damping=0.5]" → "bp_damping_0_5_").
[[nodiscard]] inline std::string test_name(std::string choice) {
  for (auto& c : choice) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return choice;
}

/// The registered component a choice names: the part before any '[' ("bp" of "bp[damping=0.5]").
[[nodiscard]] inline std::string_view component_of(std::string_view choice) {
  return choice.substr(0, choice.find('['));
}

/// One case per name of `registered`: the case of `described` whose choice (`choice_of(case)`)
/// names it, else `Case{name}`, the kit's defaults.
template <class Case, class ChoiceOf>
[[nodiscard]] std::vector<Case> cases_of(const std::vector<std::string>& registered, const std::vector<Case>& described,
                                         ChoiceOf choice_of) {
  std::vector<Case> result;
  for (const auto& name : registered) {
    const auto own = std::find_if(described.begin(), described.end(),
                                  [&](const Case& c) { return component_of(choice_of(c)) == name; });
    result.push_back(own == described.end() ? Case{name} : *own);
  }
  return result;
}

}  // namespace pgm::testing
