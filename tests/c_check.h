/* The C tests' one check: a failed condition is printed with its place and counted in `failures`
   (each test's main returns it). */
#ifndef ASPERITY_TESTS_C_CHECK_H
#define ASPERITY_TESTS_C_CHECK_H
#include <stdio.h>

static int failures = 0;
#define CHECK(condition)                                                            \
  do {                                                                              \
    if (!(condition)) {                                                             \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #condition); \
      ++failures;                                                                   \
    }                                                                               \
  } while (0)

#endif
