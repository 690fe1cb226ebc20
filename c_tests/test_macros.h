/*
 * Tiny test macros for C and C++. A test is a function `int test(void)` that returns 0 when
 * it passes; an ENSURE that fails prints where and why, and returns 1 from the test.
 * main() runs each test with RUN_TEST and returns the number that failed:
 *
 *     int main(void) { int failed = 0; failed += RUN_TEST(loads_a_file); return failed; }
 */
#ifndef BOX2SCENE_TEST_MACROS_H
#define BOX2SCENE_TEST_MACROS_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#define ENSURE(condition)                                                                    \
    do {                                                                                     \
        if (!(condition)) {                                                                  \
            fprintf(stderr, "%s:%d: failed: %s\n", __FILE__, __LINE__, #condition);          \
            return 1;                                                                        \
        }                                                                                    \
    } while (0)

/* Integers (codes, counts, lines, columns), printed when they differ. */
#define ENSURE_EQ(actual, expected)                                                          \
    do {                                                                                     \
        long long actual_ = (long long)(actual), expected_ = (long long)(expected);          \
        if (actual_ != expected_) {                                                          \
            fprintf(stderr, "%s:%d: %s is %lld, expected %lld\n", __FILE__, __LINE__,        \
                    #actual, actual_, expected_);                                            \
            return 1;                                                                        \
        }                                                                                    \
    } while (0)

/* Floats compared exactly (a parsed value against the literal it must round to). */
#define ENSURE_FLOAT(actual, expected)                                                       \
    do {                                                                                     \
        float actual_ = (actual), expected_ = (expected);                                    \
        if (memcmp(&actual_, &expected_, sizeof actual_) != 0) {                             \
            fprintf(stderr, "%s:%d: %s is %.9g, expected exactly %.9g\n", __FILE__,          \
                    __LINE__, #actual, (double)actual_, (double)expected_);                  \
            return 1;                                                                        \
        }                                                                                    \
    } while (0)

#define ENSURE_NEAR(actual, expected, tolerance)                                             \
    do {                                                                                     \
        double actual_ = (actual), expected_ = (expected);                                   \
        if (!(fabs(actual_ - expected_) <= (tolerance))) {                                   \
            fprintf(stderr, "%s:%d: %s is %.9g, expected %.9g within %g\n", __FILE__,        \
                    __LINE__, #actual, actual_, expected_, (double)(tolerance));             \
            return 1;                                                                        \
        }                                                                                    \
    } while (0)

/* NUL-terminated strings; NULL is a failure, not a crash. */
#define ENSURE_STR(actual, expected)                                                         \
    do {                                                                                     \
        const char* actual_ = (actual);                                                      \
        if (actual_ == NULL || strcmp(actual_, (expected)) != 0) {                           \
            fprintf(stderr, "%s:%d: %s is \"%s\", expected \"%s\"\n", __FILE__, __LINE__,    \
                    #actual, actual_ ? actual_ : "(null)", (expected));                      \
            return 1;                                                                        \
        }                                                                                    \
    } while (0)

static inline int box2scene_run_test(const char* name, int (*test)(void)) {
    int failed = test() != 0;
    printf("%s %s\n", failed ? "FAIL" : "pass", name);
    return failed;
}

#define RUN_TEST(test) box2scene_run_test(#test, test)

#endif /* BOX2SCENE_TEST_MACROS_H */
