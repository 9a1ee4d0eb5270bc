#include "pddl/sexpr.hpp"

#include <cctype>
#include <fstream>
#include <sstream>

namespace clips::pddl {

const std::string& SExpr::head() const {
  static const std::string empty;
  if (!is_list || items.empty() || items[0].is_list) return empty;
  return items[0].atom;
}

std::string SExpr::str() const {
  if (!is_list) return atom;
  std::string s = "(";
  for (size_t i = 0; i < items.size(); ++i) {
    if (i) s += ' ';
    s += items[i].str();
  }
  return s + ")";
}

namespace {

class Reader {
 public:
  Reader(const std::string& text, const std::string& file) : t_(text), file_(file) {}

  std::vector<SExpr> all() {
    std::vector<SExpr> out;
    for (;;) {
      skip();
      if (pos_ >= t_.size()) return out;
      out.push_back(expr());
    }
  }

 private:
  SourceLoc here() const { return SourceLoc{file_, line_, col_}; }

  void advance() {
    if (t_[pos_] == '\n') {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    ++pos_;
  }

  void skip() {
    while (pos_ < t_.size()) {
      char c = t_[pos_];
      if (c == ';') {
        while (pos_ < t_.size() && t_[pos_] != '\n') advance();
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        advance();
      } else {
        return;
      }
    }
  }

  SExpr expr() {
    SExpr e;
    e.loc = here();
    char c = t_[pos_];
    if (c == ')') throw InputError(e.loc, "unbalanced parentheses: unexpected ')'");
    if (c == '(') {
      e.is_list = true;
      advance();
      for (;;) {
        skip();
        if (pos_ >= t_.size())
          throw InputError(e.loc, "unbalanced parentheses: '(' opened here is never closed");
        if (t_[pos_] == ')') {
          advance();
          return e;
        }
        e.items.push_back(expr());
      }
    }
    std::string sym;
    while (pos_ < t_.size()) {
      char d = t_[pos_];
      if (d == '(' || d == ')' || d == ';' || std::isspace(static_cast<unsigned char>(d))) break;
      sym += static_cast<char>(std::tolower(static_cast<unsigned char>(d)));
      advance();
    }
    e.atom = std::move(sym);
    return e;
  }

  const std::string& t_;
  std::string file_;
  size_t pos_ = 0;
  int line_ = 1;
  int col_ = 1;
};

}  // namespace

std::vector<SExpr> read_sexprs(const std::string& text, const std::string& file) {
  return Reader(text, file).all();
}

SExpr read_one_sexpr(const std::string& text, const std::string& label) {
  auto all = read_sexprs(text, label);
  if (all.size() != 1)
    throw InputError(SourceLoc{label, 1, 1},
                     "expected exactly one expression, found " + std::to_string(all.size()));
  return all[0];
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLoc{path, 0, 0}, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace clips::pddl
