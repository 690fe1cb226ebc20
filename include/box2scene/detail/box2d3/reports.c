/*
 * The reports of a build (the plan's, copied) or a capture, and what the build and the
 * capture share.
 */

/* The working range of this adapter's engine version: the library's measured table
 * (docs/working-range.md), whose world settings the world def takes. */
static const b2s_working_range* b2s3_range(void) {
    return b2s_engine_working_range(B2S3_ENGINE_VERSION);
}

/* ---- reports */

typedef struct b2s3_list {
    b2s3_reports_t* reports;
    uint32_t capacity; /* of reports->items, which grows by doubling: linear in reports */
    bool out_of_memory;
} b2s3_list;

static char* b2s3_copy(const char* text) {
    if (text == NULL) {
        return NULL;
    }
    size_t size = strlen(text) + 1;
    char* copy = (char*)malloc(size);
    if (copy != NULL) {
        memcpy(copy, text, size);
    }
    return copy;
}

/* Appends a report with copies of `name` and `message`; on running out of memory, marks the
 * list and adds nothing. */
static void b2s3_add_report(b2s3_list* list, b2s_code code, const char* object, uint32_t index,
                            const char* name, const char* message) {
    b2s3_reports_t* reports = list->reports;
    if (reports->count == list->capacity) {
        uint32_t capacity = list->capacity < 8u ? 8u : 2u * list->capacity;
        b2s3_report_t* items =
            (b2s3_report_t*)realloc(reports->items, capacity * sizeof(b2s3_report_t));
        if (items == NULL) {
            list->out_of_memory = true;
            return;
        }
        reports->items = items;
        list->capacity = capacity;
    }
    b2s3_report_t* report = &reports->items[reports->count];
    report->code = code;
    report->object = object;
    report->index = index;
    report->name = b2s3_copy(name);
    report->message = b2s3_copy(message);
    if (report->message == NULL || (name != NULL && report->name == NULL)) {
        free((void*)report->name);
        free((void*)report->message);
        list->out_of_memory = true;
        return;
    }
    reports->count += 1;
}

void B2S3_API(reports_free)(b2s3_reports_t* reports) {
    if (reports == NULL) {
        return;
    }
    for (uint32_t i = 0; i < reports->count; ++i) {
        free((void*)reports->items[i].name);
        free((void*)reports->items[i].message);
    }
    free(reports->items);
    reports->items = NULL;
    reports->count = 0;
}

/* ---- what the build and the capture share */

static b2Vec2 b2s3_to_b2(b2s_vec2 v) {
    b2Vec2 out = {v.x, v.y};
    return out;
}

static b2s_vec2 b2s3_to_b2s(b2Vec2 v) {
    b2s_vec2 out = {v.x, v.y};
    return out;
}
