#pragma once
// The includes, helpers and fixtures of the pddl tests in parser_test.cpp, shared by
// the files of that name in tests/pddl/ and its label folders
// (docs/testing.md, "Labels").
// Parser: the two dataset domains and our own, and every error class with
// its message and location.
#include <gtest/gtest.h>

#include "pddl/parser.hpp"
#include "pddl/support.hpp"
#include "test_paths.hpp"

using namespace clips;
using namespace clips::pddl;

namespace parser_test {

using clips::pddl::testing::error_of;

const char* kMiniDomain = R"(
(define (domain mini)
  (:requirements :typing :adl)
  (:types box - thing thing place)
  (:predicates (at ?b - box ?p - place) (open ?p - place))
  (:action go :parameters (?b - box ?p - place)
     :precondition (open ?p) :effect (at ?b ?p)))
)";

}  // namespace parser_test
using namespace parser_test;
