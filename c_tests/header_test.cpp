// header_test.c compiled as pedantic C++17: box2scene.h must be valid C++ as it is C.
#include "header_test.c"
