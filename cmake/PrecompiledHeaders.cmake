# Precompiled headers where no compiler cache is there: a new user's first build and CI's clean
# room compile every file once, and most of a test's time is parsing Qt's and Eigen's headers
# (tests/ui/tst_ui_payload.cpp took 17 s to compile, 10 s with QtCore and Eigen precompiled).
# With ccache (scripts/deps.sh uses it when it is installed) they are off by default: ccache does not
# cache a compile that reads a precompiled header unless told to trust it, and its hits are
# faster still. GCC checks that a precompiled header was made with the same macros and flags as
# the file that reads it (-Winvalid-pch) and parses the headers themselves when not, so a
# mismatch costs time, never correctness.
if(CMAKE_CXX_COMPILER_LAUNCHER)
    set(LEARNID_PCH_DEFAULT OFF)
else()
    set(LEARNID_PCH_DEFAULT ON)
endif()
option(LEARNID_PRECOMPILED_HEADERS "Precompile Qt's and Eigen's headers (default: on without ccache)"
       ${LEARNID_PCH_DEFAULT})

# The headers nearly every file of the project reads.
set(LEARNID_PCH_HEADERS <QtCore> <Eigen/Dense>)

# learnid_precompile(target [HEADERS...]): target's own precompiled headers, LEARNID_PCH_HEADERS
# and HEADERS (for a library of many files).
function(learnid_precompile target)
    if(LEARNID_PRECOMPILED_HEADERS)
        target_precompile_headers(${target} PRIVATE ${LEARNID_PCH_HEADERS} ${ARGN})
    endif()
endfunction()

# learnid_share_folder_pch(target): the precompiled headers of target's folder, made once by an
# object library, for the many one-file executables of a folder (tests), each of which would
# otherwise parse them. GCC uses them only in a file compiled with every macro they were made
# with, defined the same way (it tells, -Winvalid-pch, and parses the headers instead), so they
# are made with the fewest: QtTest's (the folder's own test paths), target's at this call, and
# Eigen's include path, which every caller must have too.
function(learnid_share_folder_pch target)
    if(NOT LEARNID_PRECOMPILED_HEADERS)
        return()
    endif()
    file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
    string(MAKE_C_IDENTIFIER "learnid_pch_${folder}" pch)
    if(NOT TARGET ${pch})
        set(source "${CMAKE_CURRENT_BINARY_DIR}/${pch}.cpp")
        file(CONFIGURE OUTPUT "${source}" CONTENT "// the precompiled headers of ${folder}\n")
        add_library(${pch} OBJECT "${source}")
        set_target_properties(${pch} PROPERTIES AUTOMOC OFF AUTOUIC OFF AUTORCC OFF)
        target_link_libraries(${pch} PRIVATE Qt6::Test Eigen3::Eigen)
        get_target_property(definitions ${target} COMPILE_DEFINITIONS)
        if(definitions)
            target_compile_definitions(${pch} PRIVATE ${definitions})
        endif()
        target_precompile_headers(${pch} PRIVATE ${LEARNID_PCH_HEADERS})
    endif()
    target_precompile_headers(${target} REUSE_FROM ${pch})
endfunction()
