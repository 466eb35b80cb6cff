#pragma once
// Printer for the native Grafcet text format (.g7): load_g7(write_g7(p)) gives a model
// structurally equal to p (source locations aside).

#include <stdexcept>
#include <string>

#include "model/chart.hpp"
#include "model/errors.hpp"

namespace sfcv::io {

/// Thrown by write_g7 when the model holds what .g7 cannot express (several POUs, ST action
/// bodies, qualifiers other than N, priorities, TIME or FB variables, ...); the message names
/// the construct and its place.
class G7WriteError : public UnsupportedConstruct {
 public:
  using UnsupportedConstruct::UnsupportedConstruct;
};

std::string write_g7(const model::Project& project);

}  // namespace sfcv::io
