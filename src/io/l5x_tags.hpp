#pragma once
// Internal header of sfcv_io (only src/io includes it; cmake/CheckInternalHeaders.cmake).
// Structured tags of Studio 5000 `.L5X` files: tags of a user data type (`<DataType>` of the
// controller), arrays, and the controller's TIMERs. Rungs address their parts by member,
// constant index and bit (`Cooker1.BIT_Logic[0].2`, `Cooker1.TMR_Logic[3].DN`); the reader
// models each part the rungs use as its own variable, named by its path
// (`Cooker1_BIT_Logic_0`), and leaves the rest out: a program's 50-element timer array whose
// rungs use three of them is three TON instances, not fifty.

#include <cstdint>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <vector>

namespace sfcv::io::l5x {

/// A tag read part by part.
struct StructuredTag {
  pugi::xml_node node;          ///< its <Tag>
  std::string name;             ///< as declared
  std::string data_type;        ///< DINT, TIMER, a user type...
  std::vector<int> dimensions;  ///< empty: not an array
  bool global = false;          ///< a controller tag
  bool consumed = false;        ///< TagType Consumed: another controller writes it
};

enum class LeafKind { Bool, Int, Timer, Counter, Other };

/// The part of a structured tag an operand addresses, down to a BOOL, an integer, a TIMER or a
/// COUNTER.
struct TagLeaf {
  const StructuredTag* tag = nullptr;
  std::string path;      ///< members spelled as declared: `Cooker1.BIT_Logic[0]`
  std::string variable;  ///< the model's name for it: `Cooker1_BIT_Logic_0`
  LeafKind kind = LeafKind::Other;
  std::string type_name;  ///< BOOL, DINT, TIMER, COUNTER, REAL...
  std::string rest;       ///< what the operand names below the leaf: a bit (`2`), `DN`, or ""
  pugi::xml_node value;   ///< its decorated data: a node with a Value, or a TIMER's structure
};

/// The controller's user data types, and how operands walk them.
class TagTypes {
 public:
  TagTypes() = default;
  /// `data_types`: the controller's <DataTypes> (may be null).
  explicit TagTypes(pugi::xml_node data_types);

  bool is_user_type(const std::string& name) const;

  /// The leaf `operand` (which starts with `tag.name`) addresses; nullopt with `error` set when
  /// it is not one this reader models (a whole array or structure, an index that is a tag).
  /// `whole_array`: when `operand` names a whole array, its dimensions go there (no error).
  std::optional<TagLeaf> resolve(const StructuredTag& tag, const std::string& operand,
                                 std::string& error, std::vector<int>* whole_array = nullptr) const;

  /// `operand` with one index that is not a constant (`Recipe.Step[Index].Heat`), read as the
  /// element that index chooses: the index's operand and each element's (`Recipe.Step[3].Heat`).
  /// nullopt with `error` empty when every index is a constant.
  struct Indexed {
    std::string index;
    std::vector<std::string> elements;
  };
  std::optional<Indexed> indexed(const StructuredTag& tag, const std::string& operand,
                                 std::string& error) const;

 private:
  std::map<std::string, pugi::xml_node> types_;  ///< upper-case name -> <DataType>
};

/// Elements an operand with a tag for index may choose among (each is a variable of the model).
inline constexpr int kMaxIndexedElements = 1024;

/// The dimensions of a tag (`Dimensions="10"`, `"4 3"`); nullopt if not read.
std::optional<std::vector<int>> tag_dimensions(const std::string& text);

/// The initial value decorated data gives a BOOL or integer leaf (0 when none is written);
/// nullopt when the value is not an integer literal.
std::optional<std::int64_t> leaf_initial(const TagLeaf& leaf);

/// A member (PRE, ACC, DN...) of a TIMER or COUNTER leaf's decorated data (0 when none is
/// written).
std::int64_t leaf_member(const TagLeaf& leaf, const char* member);

}  // namespace sfcv::io::l5x
