#pragma once
// The includes, helpers and fixtures of the pddl tests in limits_test.cpp, shared by
// the files of that name in tests/pddl/ and its label folders
// (docs/testing.md, "Labels").
// Limits that hold on input built to exhaust memory or slip wrong values in:
// the grounder counts the reachable ground actions against its limit, the
// reader stops huge or malformed files early, and costs and parameter lists
// are checked.
#include <gtest/gtest.h>

#include "pddl/parser.hpp"
#include "pddl/task.hpp"
#include "pddl/support.hpp"

using namespace clips;
using namespace clips::pddl;

namespace limits_test {

using clips::pddl::testing::error_of;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// One 3-parameter action over `n` objects, `rooms` of which are rooms (a
// static unary precondition on ?z).
const char* kLinkDomain = R"((define (domain links)
  (:requirements :strips :typing)
  (:types thing)
  (:predicates (linked ?x ?y ?z - thing) (room ?z - thing))
  (:action link :parameters (?x ?y ?z - thing)
    :precondition (and (room ?z) (not (linked ?x ?y ?z)))
    :effect (linked ?x ?y ?z)))
)";

std::string link_problem(int n, int rooms) {
  std::string objs, init;
  for (int i = 0; i < n; ++i) objs += " o" + std::to_string(i);
  for (int i = 0; i < rooms; ++i) init += " (room o" + std::to_string(i) + ")";
  return "(define (problem p) (:domain links) (:objects" + objs + " - thing) (:init" + init + ") (:goal (and)))";
}

std::shared_ptr<const Task> ground_links(int n, int rooms, int64_t limit) {
  auto d = std::make_shared<Domain>(parse_domain(kLinkDomain, "links.pddl"));
  auto p = std::make_shared<Problem>(parse_problem(*d, link_problem(n, rooms), "p.pddl"));
  GroundingOptions opts;
  opts.max_ground_actions = limit;
  return std::make_shared<Task>(d, p, opts);
}

}  // namespace limits_test
using namespace limits_test;
