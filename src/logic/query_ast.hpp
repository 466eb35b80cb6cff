#pragma once
// Syntax tree of the set query language (seed 002's 13 operators, docs/queries.md). The tree is
// untyped: whether a name is a set, a step or an output is decided when the query is compiled
// against a transition system (query_compile.hpp), because library parameters are substituted
// first and take their meaning from where they are used.

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "model/errors.hpp"
namespace sfcv::logic {

/// Where a piece of query text comes from: "query" (the command line), a library file name.
struct QueryPos {
  std::shared_ptr<const std::string> source;
  std::uint32_t line = 1;
  std::uint32_t column = 1;
  std::string str() const;  ///< "query:1:7"
};

/// A syntax, name or sort error, located in the query text or a library file.
class QueryError : public InputError {
 public:
  QueryError(const QueryPos& pos, const std::string& message)
      : InputError(pos.str() + ": " + message), pos_(pos), message_(message) {}
  const QueryPos& pos() const { return pos_; }
  const std::string& message() const { return message_; }

 private:
  QueryPos pos_;
  std::string message_;
};

enum class NodeKind {
  Name,        ///< name: a let/parameter, Y, T, Y0, Steps, a step, an input or output
  Integer,     ///< value
  EmptySet,    ///< {}
  StepList,    ///< {1, 10, X3}: args are Name/Integer elements
  SetBuilder,  ///< { name in args[0] | args[1] }
  Call,        ///< name(args...): an operator or a library definition
  Let,         ///< let name = args[0]; args[1]
  Union,
  Inter,
  Diff,  ///< A + B, A * B, A - B
  And,
  Or,
  Not,    ///< & | !  (tests, and input/output expressions)
  Count,  ///< #A
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,  ///< = != < <= > >=
};

struct Node;
using NodePtr = std::shared_ptr<const Node>;

struct Node {
  NodeKind kind = NodeKind::Name;
  std::string name;
  std::int64_t value = 0;
  std::vector<NodePtr> args;
  QueryPos pos;
  std::uint32_t height = 1;  ///< 1 + the largest height of `args` (at most model::kMaxNesting)
};

/// Prints a node back in the concrete syntax, fully parenthesised where needed.
std::string to_string(const Node& n);

/// Parses a query: `let x = e; ... e`. Throws QueryError with the position of the problem.
NodePtr parse_query(std::string_view text, const std::string& source_name = "query");

/// A named, parameterised query of a library: `def name(a, b) = body;`.
struct Definition {
  std::string name;
  std::vector<std::string> params;
  NodePtr body;
  QueryPos pos;
  std::string doc;  ///< the `//` comment lines just above the definition
};

/// Parses a library file: definitions separated by `;`, `//` comments.
std::vector<Definition> parse_library(std::string_view text, const std::string& source_name);

}  // namespace sfcv::logic
