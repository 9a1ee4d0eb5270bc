#pragma once
// Noun-less deixis. "Could you grab me one more of these?" right after the
// speaker took a can means another can; the language model reads commands
// and words, not what was done, so the words that stand for the kind are
// replaced by its noun before scoring: "Could you grab me one more can?".
#include <string>

namespace clips::language {

// The noun and plural people use for objects of a PDDL type ("can", "cans";
// the type's first WordNet noun phrase, else its name as words).
struct KindNoun {
  std::string singular, plural;
};
KindNoun kind_noun(const std::string& type);

// `text` with its noun-less references to a kind ("one more of these",
// "another one of those", "some more of them", "another one", a final
// "one more" or "another") naming `kind` instead; unchanged when it has none
// or `kind` is empty. "this"/"that" alone are left as they are: they may
// point at anything.
std::string resolve_deixis(const std::string& text, const KindNoun& kind);
// The same, and where it resolved a reference, "not the EXCEPT one" added
// before the final punctuation: "another one of these" is not the one the
// speaker just had (`except`: a quality value only that one has; empty:
// nothing added).
std::string resolve_deixis(const std::string& text, const KindNoun& kind, const std::string& except);

}  // namespace clips::language
