// Reuses the math tests' allocation counter (replacement operator new) in this executable.
#include "../../math/test/allocation_counter_test.cpp"
