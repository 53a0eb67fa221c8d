// The Catch2 main for polyroll's tests.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
