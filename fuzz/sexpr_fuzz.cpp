// The s-expression reader: any bytes either read or raise SyntaxError, and
// what was read prints back to text that reads the same again.
#include <cstdlib>

#include "fuzz/fuzz_target.hpp"
#include "pddl/sexpr.hpp"

CLIPS_FUZZ_TARGET(sexpr) {
  using namespace clips::pddl;
  const std::string text = clips::fuzz::as_text(data, size);
  (void)printable(text, 64);
  std::vector<SExpr> exprs;
  try {
    exprs = read_sexprs(text, "<fuzz>");
  } catch (const clips::InputError&) {
    return 0;
  }
  for (const SExpr& e : exprs) {
    const std::string once = e.str();
    // After a space: a leading byte-order mark is dropped by the reader, but
    // elsewhere it is an ordinary symbol.
    const SExpr again = read_one_sexpr(" " + once, "<fuzz:str>");
    if (again.str() != once) std::abort();  // str() must be a faithful printer
  }
  return 0;
}
