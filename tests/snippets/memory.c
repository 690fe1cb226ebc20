/* The harness of a C snippet that loads a scene from memory: `bytes` and `size` are
 * level.xml's content. */
#include "snippet_head.h"

#include <box2scene.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* The body's own function, so that its `return 1` leaves it and the harness frees `bytes`. */
static int snippet(const uint8_t* bytes, size_t size) {
#include "snippet_body.h"
    return 0;
}

int main(void) {
    FILE* file = fopen("level.xml", "rb");
    if (file == NULL) {
        perror("level.xml");
        return 1;
    }
    uint8_t* bytes = NULL;
    size_t size = 0, capacity = 0, got;
    do {
        if (size == capacity) {
            capacity = capacity ? 2 * capacity : 1 << 16;
            uint8_t* grown = (uint8_t*)realloc(bytes, capacity);
            if (grown == NULL) {
                free(bytes);
                fclose(file);
                return 1;
            }
            bytes = grown;
        }
        got = fread(bytes + size, 1, capacity - size, file);
        size += got;
    } while (got > 0);
    fclose(file);
    int status = snippet(bytes, size);
    free(bytes);
    return status;
}
