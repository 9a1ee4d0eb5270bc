// issue 46 inputs at the PDDL layer: names that are not UTF-8 (a Latin-1
// file), a type hierarchy that makes `object` a subtype, and files that are
// not regular files (a FIFO would block the reader, /dev/zero never end).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>

#include "pddl/parser.hpp"
#include "pddl/sexpr.hpp"
#include "util/error.hpp"

namespace clips::pddl {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PddlHardening, NamesThatAreNotUtf8AreRefusedWithTheirPlace) {
  // "kuchen" + 0xFC (u-umlaut in Latin-1) as a type name on line 2.
  const std::string domain = "(define (domain d)\n  (:types kuchen\xfc)\n  (:predicates (p ?x)))";
  const std::string e = error_of([&] { parse_domain(domain, "latin1.pddl"); });
  EXPECT_NE(e.find("latin1.pddl:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("not valid UTF-8"), std::string::npos) << e;
  EXPECT_NE(e.find("kuchen\\xfc"), std::string::npos) << e;
  // The same name in UTF-8 reads.
  EXPECT_NO_THROW(parse_domain("(define (domain d)\n  (:types kuchen\xc3\xbc)\n  (:predicates (p ?x)))", "utf8.pddl"));
}

TEST(PddlHardening, ObjectCannotBeASubtype) {
  const std::string e =
      error_of([] { parse_domain("(define (domain d) (:types dish - object object - dish) (:predicates (p ?x)))", "t.pddl"); });
  EXPECT_NE(e.find("cyclic type hierarchy"), std::string::npos) << e;
  EXPECT_NE(e.find("'object'"), std::string::npos) << e;
  // "object" on its own (no parent) is still allowed.
  EXPECT_NO_THROW(parse_domain("(define (domain d) (:types dish object) (:predicates (p ?x)))", "t.pddl"));
}

TEST(PddlHardening, OnlyRegularFilesAreRead) {
  const std::string fifo = ::testing::TempDir() + "/clips-fifo-" + std::to_string(getpid());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Returns at once (a FIFO would block an open until a writer came).
  const std::string e = error_of([&] { read_text_file(fifo); });
  std::filesystem::remove(fifo);
  EXPECT_NE(e.find("not a regular file"), std::string::npos) << e;
  const std::string z = error_of([] { read_text_file("/dev/zero"); });
  EXPECT_NE(z.find("/dev/zero"), std::string::npos) << z;
  EXPECT_NE(z.find("not a regular file"), std::string::npos) << z;
}

}  // namespace
}  // namespace clips::pddl
