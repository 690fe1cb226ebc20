/* The harness of a C snippet that is a function body on its own: it runs as main's. */
#include "snippet_head.h"

int main(void) {
#include "snippet_body.h"
    return 0;
}
