#pragma once
// A random grafcet for differential tests (BDD engine vs explicit RSG, circuit vs explicit
// evolutions), reproducible from a seed.

#include <functional>
#include <random>

#include "support/grafcet_builder.hpp"

namespace sfcv::test {

/// A random grafcet from `seed`: two partial grafcets synchronised by step variables, guards
/// from inputs, edges, delays, an integer input, step variables; continuous actions with
/// conditions, stored actions (Boolean and a bounded counter), and optionally a forcing order,
/// a macro-step or an enclosing step (whose grafcet may enter at an activation-linked step).
inline model::Project random_grafcet(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto pick = [&](std::uint32_t n) { return static_cast<std::uint32_t>(rng() % n); };
  GrafcetBuilder b;
  b.input("a").input("b").input("c").input("n", model::Type::integer("INT", 0, 9));
  b.output("y").output("z").output("w").output("f");
  b.pou().variables.push_back({"cnt",
                               model::VarDirection::Local,
                               model::Type::integer("INT", 0, 3),
                               std::nullopt,
                               "",
                               {},
                               {},
                               {}});
  const std::uint32_t n1 = 3 + pick(3), n2 = 2 + pick(2);
  const bool macro = pick(4) == 0, enclosing = !macro && pick(4) == 0, forcing = pick(3) == 0;
  auto s1 = [](std::uint32_t i) { return std::to_string(1 + i); };
  auto s2 = [](std::uint32_t i) { return std::to_string(21 + i); };
  auto input = [&]() -> model::ExprPtr {
    static const char* names[] = {"a", "b", "c"};
    return v(names[pick(3)]);
  };
  std::function<model::ExprPtr(int)> guard = [&](int depth) -> model::ExprPtr {
    switch (pick(depth > 0 ? 12 : 9)) {
      case 0:
        return input();
      case 1:
        return not_(input());
      case 2:
        return rise(input());
      case 3:
        return fall(input());
      case 4:
        return v("X" + s2(pick(n2)));
      case 5:
        return v("X" + s1(pick(n1)));
      case 6:
        return cmp(pick(2) ? model::ExprKind::Ge : model::ExprKind::Lt, v("n"), num(1 + pick(8)));
      case 7:
        return model::make_delay(1000, v("X" + s1(pick(n1))), pick(2) ? 0 : 500);
      case 8:
        return pick(2) ? lit(true) : rise(v("X" + s2(pick(n2))));
      case 9:
        return not_(guard(depth - 1));
      default:
        return and_(guard(depth - 1), guard(depth - 1));
    }
  };
  b.chart("G1");
  for (std::uint32_t i = 0; i < n1; ++i) {
    if (macro && i == n1 - 1)
      b.step("M9", false, model::StepKind::MacroStep, {"X9"});
    else if (enclosing && i == n1 - 1)
      b.step(s1(i), false, model::StepKind::Enclosing, {"G3"});
    else
      b.step(s1(i), i == 0);
  }
  auto g1_name = [&](std::uint32_t i) { return macro && i == n1 - 1 ? std::string("M9") : s1(i); };
  for (std::uint32_t i = 0; i < n1; ++i) {
    b.transition({g1_name(i)}, {g1_name((i + 1) % n1)}, guard(2));
    if (pick(3) == 0) b.transition({g1_name(i)}, {g1_name(pick(n1))}, guard(1));
  }
  b.continuous(s1(pick(n1 - 1)), "y", pick(2) ? guard(1) : nullptr);
  b.stored(s1(pick(n1 - 1)), model::StoredWhen::Activation, "z", lit(true));
  b.stored(s1(pick(n1 - 1)),
           pick(2) ? model::StoredWhen::Deactivation : model::StoredWhen::Activation, "z",
           lit(false));
  if (pick(2))
    b.stored(s1(pick(n1 - 1)), model::StoredWhen::Activation, "cnt",
             model::make_binary(model::ExprKind::Add, v("cnt"), num(1)));
  else
    b.stored(s1(pick(n1 - 1)), model::StoredWhen::Event, "f", lit(true), rise(input()));
  if (forcing) {
    const auto k = pick(3);
    b.forcing(s1(1 + pick(n1 - 2)), "G2",
              k == 0   ? model::ForcingKind::Situation
              : k == 1 ? model::ForcingKind::Initial
                       : model::ForcingKind::Current,
              k == 0 ? std::vector<std::string>{s2(pick(n2))} : std::vector<std::string>{});
  }
  b.chart("G2");
  for (std::uint32_t i = 0; i < n2; ++i) b.step(s2(i), i == 0);
  for (std::uint32_t i = 0; i < n2; ++i) b.transition({s2(i)}, {s2((i + 1) % n2)}, guard(2));
  b.continuous(s2(pick(n2)), "w", nullptr);
  b.stored(s2(pick(n2)), model::StoredWhen::Activation, "cnt", num(pick(2)));
  if (macro) {
    b.chart("X9");
    b.step("E9").step("S9");
    b.transition({"E9"}, {"S9"}, guard(1));
  }
  if (enclosing) {
    b.chart("G3");
    b.step("31", true).step("32");
    b.transition({"31"}, {"32"}, guard(1));
    b.transition({"32"}, {"31"}, guard(1));
  }
  // Sometimes the continuous output y is also written by a stored action (read as either,
  // docs/semantics.md 2.7); drawn last so that the charts above do not change with it.
  if (pick(3) == 0) {
    const auto step = s1(pick(n1 - 1));
    const auto when = pick(2) ? model::StoredWhen::Deactivation : model::StoredWhen::Activation;
    b.stored(step, when, "y", lit(pick(2) == 0));
    b.pou().stored_actions.back().chart = "G1";
  }
  // Sometimes G3 enters at an activation-linked step (docs/semantics.md 2.12): 32 linked, with
  // or without 31 still marked initial; drawn last, for the same reason.
  if (enclosing) {
    if (const auto k = pick(3); k > 0)
      for (auto& c : b.pou().charts)
        if (c.name == "G3") {
          c.steps[1].activation_link = true;
          c.steps[0].initial = k == 1;
        }
  }
  return b.project();
}

}  // namespace sfcv::test
