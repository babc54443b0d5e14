# learnid_public_headers(<target> <folder>): makes core/<folder>/*.h reachable as
# "<folder>/X.h" for <target> and whoever links it, and for no one else. Each core library gets
# an include root of its own in the build tree, <build>/include/<folder>, holding one link
# <folder> -> core/<folder>; there is no include path to core/ as a whole. So a header of a
# library that is not linked cannot be included: the build holds the layering (docs/design.md
# §3), e.g. session including a canrobot header fails to compile.
function(learnid_public_headers target folder)
    set(root "${PROJECT_BINARY_DIR}/include/${folder}")
    if(NOT IS_SYMLINK "${root}/${folder}")
        file(MAKE_DIRECTORY "${root}")
        file(CREATE_LINK "${PROJECT_SOURCE_DIR}/core/${folder}" "${root}/${folder}" SYMBOLIC)
    endif()
    target_include_directories(${target} PUBLIC "${root}")
endfunction()
