// Value-range analysis: an interval per component of every IR value, from declared parameter
// ranges (the runtime rejects values outside them, so the analysis is sound), colour
// parameters ([0, 1] linear), attribute ranges (unit normals) and the ranges of built-ins,
// propagated through every operation by interval arithmetic.
//
// Later stages ask it what a value can be: the precision policy (can this stay mediump?),
// and the lint (can this overflow fp16's 65504 or lose a small value below 2^-14?).
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "facet/ir/module.h"

namespace facet::ir {

struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool bounded() const {
    return lo > -std::numeric_limits<double>::infinity() && hi < std::numeric_limits<double>::infinity();
  }
  bool contains(double x) const { return lo <= x && x <= hi; }
  bool operator==(const Interval&) const = default;
};

struct ValueRange {
  int components = 1;
  std::array<Interval, 4> c{};
  // The smallest interval holding every component.
  Interval hull() const;
};

class RangeMap {
 public:
  const ValueRange& of(ValueId id) const { return ranges_[id]; }
  // The range of a written output, or nullopt if the material does not write it.
  std::optional<ValueRange> output(const std::string& name) const;

 private:
  friend RangeMap analyse_ranges(const Material& material);
  std::vector<ValueRange> ranges_;
  std::map<std::string, ValueId> outputs_;
};

RangeMap analyse_ranges(const Material& material);

}  // namespace facet::ir
