#pragma once
// The semantic frame of a lifted command, as the embedded language model sees it.
//
// A printed command such as
//   (handover you me key1) (handover you me key2) (unlock you key3 door1)
//     where (iscolor key1 red) (iscolor key2 red) (iscolor door1 blue)
// is reduced to *groups*: actions that share (agent, action name, type of the
// focal object). Each group records how many actions it holds (this drives
// number words and plural nouns) and the distinct attribute values (colours)
// of its focal objects, in first-appearance order. For the example:
//   group 1: agent you, action handover, recipient me, type key, count 2, colours {red}
//   group 2: agent you, action unlock, type door, count 1, colours {blue}
// The focal object of an action is its last argument that is not a pronoun
// (pickup: the item, handover: the item, unlock: the door, grab: the item).
// Variable names are lifted (key1, ?gem1, plate2): the type is the name with
// '?' and trailing digits removed; an (itemtype v T) predicate overrides it.
// Any other two-argument predicate (p v value) attaches `value` to v as an
// attribute (a qualifier: colour, size, material, owner, ...), remembering
// which predicate it came from. A value marked with its number ("shelf#3",
// util::number_marked) also gives the group that number.
#include <string>
#include <string_view>
#include <vector>

namespace clips::lm {

struct FrameGroup {
  std::string agent;        // "you" (listener) or "me" (speaker)
  std::string action;       // e.g. "pickup"
  bool to_speaker = false;  // a non-agent argument is "me" (handover you me x)
  std::string type;         // focal object type, "" if none
  int count = 0;            // number of actions in the group
  std::vector<std::string> attributes;  // distinct attribute words, e.g. {"red"}
  // The qualifier predicate each attribute came from ("iscolor", "issize"),
  // parallel to `attributes`: a value only contradicts values of its own kind.
  std::vector<std::string> attribute_predicates;
  // The numbers of numbered place values ("shelf#3" -> attribute "shelf",
  // number "3"), each a unit of its own that people may or may not say.
  std::vector<std::string> numbers;
};

struct CommandFrame {
  std::vector<FrameGroup> groups;
  int num_actions = 0;
};

// Parse a printed command. Throws LmError (with `what_for` in the message) if
// the text is not a sequence of parenthesised terms with an optional `where`.
// The empty string parses to an empty frame.
CommandFrame parse_command_frame(std::string_view command, std::string_view what_for);

// Type of a lifted variable name: "?cutleryfork2" -> "cutleryfork", "Plate1" -> "plate".
std::string variable_type(std::string_view name);

}  // namespace clips::lm
