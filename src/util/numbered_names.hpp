#pragma once
// Names that carry a number people say ("shelf3" beside shelf1 and shelf2:
// "shelf 3", "the third shelf"), and the mark that tells the embedded
// language model to read the number as a word of its own ("shelf#3").
#include <string>
#include <vector>

namespace clips::util {

// The names among `names` that are a word stem and a number ("shelf3",
// "bed-2") sharing their stem with another such name: the ones people tell
// apart by saying the number. Sorted.
std::vector<std::string> numbered_names(const std::vector<std::string>& names);
// "shelf3" -> "shelf#3" (the stem, '#', the number); other names unchanged.
std::string number_marked(const std::string& name);
// The same over the whole-word occurrences of `names` in a printed command.
std::string mark_numbered(const std::string& command, const std::vector<std::string>& names);

}  // namespace clips::util
