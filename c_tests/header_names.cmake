# Writes OUT, a C header that uses every macro and every enumeration constant HEADER
# (include/box2scene.h) defines, as a host would use it: a number as an integer constant, a
# string as a string, a brace list as an array's initializer. header_test.c includes it and
# checks what it lists, so that a name the header gives and C cannot compile fails the build,
# and a macro added to the header is in the test without anyone adding it.
#   cmake -DHEADER=include/box2scene.h -DOUT=header_names.h -P header_names.cmake

file(STRINGS "${HEADER}" lines)
set(constants "")
set(strings "")
set(lists "")
set(list_table "")
set(enumeration "")
set(list_count 0)
set(guard "")
foreach(line IN LISTS lines)
    if(line MATCHES "^enum (b2s_[a-z0-9_]+)")
        set(enumeration "${CMAKE_MATCH_1}")
    elseif(line MATCHES "^};")
        set(enumeration "")
    elseif(enumeration AND line MATCHES "^  ([A-Z][A-Z0-9_]*)( = [^,]*)?,$")
        string(APPEND constants
            "    {\"${enumeration}\", \"${CMAKE_MATCH_1}\", (unsigned long long)(${CMAKE_MATCH_1})},\n")
    elseif(line MATCHES "^#define ([A-Za-z_][A-Za-z0-9_]*)(.*)$")
        set(name "${CMAKE_MATCH_1}")
        string(STRIP "${CMAKE_MATCH_2}" value)
        if(value MATCHES "^\\(")
            message(FATAL_ERROR "${HEADER}: ${name} is a function-like macro: "
                "header_names.cmake knows no use of one; teach it one")
        elseif(value STREQUAL "")
            # Only the include guard is defined empty; header_test.c checks it.
            if(NOT guard STREQUAL "")
                message(FATAL_ERROR "${HEADER}: ${name} is defined empty besides ${guard}")
            endif()
            set(guard "${name}")
        elseif(value MATCHES "^\"")
            string(APPEND strings "    {\"${name}\", ${name}},\n")
        elseif(value MATCHES "^{")
            string(APPEND lists
                "static const unsigned long long header_list_${list_count}[] = ${name};\n")
            string(APPEND list_table "    {\"${name}\", header_list_${list_count}, "
                "sizeof header_list_${list_count} / sizeof header_list_${list_count}[0]},\n")
            math(EXPR list_count "${list_count} + 1")
        else()
            string(APPEND constants "    {NULL, \"${name}\", (unsigned long long)(${name})},\n")
        endif()
    endif()
endforeach()
if(NOT guard STREQUAL "BOX2SCENE_H")
    message(FATAL_ERROR "${HEADER}: no include guard BOX2SCENE_H found")
endif()

file(WRITE "${OUT}.new" "/* Generated from box2scene.h by c_tests/header_names.cmake: do not edit. */
#include <stddef.h>

/* Every number the header names: its enumeration's name (NULL for a macro), its own, its value. */
typedef struct {
    const char* enumeration;
    const char* name;
    unsigned long long value;
} header_constant;
static const header_constant header_constants[] = {
${constants}    {NULL, NULL, 0},
};

/* Every string macro: its name and its value. */
static const char* const header_strings[][2] = {
${strings}    {NULL, NULL},
};

/* Every brace-list macro, as the initializer of an array. */
${lists}typedef struct {
    const char* name;
    const unsigned long long* values;
    size_t count;
} header_list;
static const header_list header_lists[] = {
${list_table}    {NULL, NULL, 0},
};
")
# Rewritten only when it changes, so that the test is not rebuilt for nothing.
file(COPY_FILE "${OUT}.new" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.new")
