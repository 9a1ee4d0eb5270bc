#pragma once
// Everything of the public clips API.
#include "clips/errors.hpp"
#include "clips/policy.hpp"
#include "clips/session.hpp"
#include "clips/version.hpp"
