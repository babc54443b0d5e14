# cmake -P PackageTest.cmake with -DCPACK= -DDPKG= -DDPKG_DEB= -DOBJDUMP= -DCONFIG=<CPackConfig>
# -DWORK=<scratch dir> -DVERSION=<project version> -DPROGRAMS=a,b,c [-DMISSING=tools not found]
# Builds the .deb, unpacks it with dpkg -x and checks it: control fields, files, the Qt
# libraries the binaries link among the Depends, no absolute RPATH, and the installed
# executables running from the scratch root with the system's Qt (LD_LIBRARY_PATH unset).
cmake_minimum_required(VERSION 3.24)
string(REPLACE "," ";" PROGRAMS "${PROGRAMS}")
if(MISSING)
    message(FATAL_ERROR "cannot build the package, not found at configure time: ${MISSING} "
                        "(scripts/deps.sh installs dpkg-dev, binutils and file)")
endif()

function(run what)  # run(<what> <command...>): runs it, fails naming <what>; sets OUT
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                    WORKING_DIRECTORY "${WORK}/workspace")
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "${what} failed (${rc}):\n${ARGN}\nstdout:\n${out}\nstderr:\n${err}")
    endif()
    set(OUT "${out}" PARENT_SCOPE)
endfunction()

function(expect condition message)  # expect("<if() condition>" "<what is wrong>")
    cmake_language(EVAL CODE "
        if(NOT (${condition}))
            message(FATAL_ERROR [==[${message}]==])
        endif()")
endfunction()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/workspace" "${WORK}/root")

# 1. The package, built in a scratch output directory from the build tree's CPack config.
run("cpack" "${CPACK}" -G DEB --config "${CONFIG}" -B "${WORK}/out")
file(GLOB debs "${WORK}/out/*.deb")
list(LENGTH debs count)
expect("count EQUAL 1" "expected one .deb in ${WORK}/out, found ${count}: ${debs}")
message(STATUS "package: ${debs}")

# 2. Control fields.
run("dpkg-deb -f Package" "${DPKG_DEB}" -f "${debs}" Package)
string(STRIP "${OUT}" package)
expect("package STREQUAL \"learnid\"" "Package is '${package}', expected learnid")
run("dpkg-deb -f Version" "${DPKG_DEB}" -f "${debs}" Version)
string(STRIP "${OUT}" version)
expect("version STREQUAL VERSION" "Version is '${version}', expected the project version ${VERSION}")
run("dpkg-deb -f Depends" "${DPKG_DEB}" -f "${debs}" Depends)
string(STRIP "${OUT}" depends)
message(STATUS "Depends: ${depends}")

# 3. Unpack into the scratch root: every file where it belongs.
run("dpkg -x" "${DPKG}" -x "${debs}" "${WORK}/root")
set(root "${WORK}/root")
foreach(file usr/share/applications/learnid.desktop
             usr/share/icons/hicolor/scalable/apps/learnid.svg)
    expect("EXISTS \"${root}/${file}\"" "the package lacks /${file}")
endforeach()
file(STRINGS "${root}/usr/share/applications/learnid.desktop" entry REGEX "^(Exec|Icon)=")
expect("\"Exec=learnid %f;Icon=learnid\" STREQUAL entry"
       "desktop entry Exec/Icon are '${entry}', expected Exec=learnid %f;Icon=learnid")

# 4. Each executable: present, no absolute RPATH, and every Qt library it links is
# in Depends (libQt6Foo.so.6 is Debian's libqt6foo6).
foreach(program IN LISTS PROGRAMS)
    set(binary "${root}/usr/bin/${program}")
    expect("EXISTS \"${binary}\"" "the package lacks /usr/bin/${program}")
    run("objdump -p ${program}" "${OBJDUMP}" -p "${binary}")
    # qt_standard_project_setup() gives $ORIGIN-relative entries; an absolute one would point
    # into the build machine.
    expect("NOT OUT MATCHES \"R(UN)?PATH +([^\n]*:)?/\""
           "/usr/bin/${program} has an absolute RPATH/RUNPATH entry:\n${OUT}")
    string(REGEX MATCHALL "NEEDED +libQt6[A-Za-z]+\\.so\\.6" needed "${OUT}")
    expect("needed" "/usr/bin/${program} links no Qt 6 library?")
    foreach(lib IN LISTS needed)
        string(REGEX REPLACE "NEEDED +libQt6([A-Za-z]+)\\.so\\.6" "libqt6\\16" pkg "${lib}")
        string(TOLOWER "${pkg}" pkg)
        expect("depends MATCHES \"(^|, )${pkg}( |,|$)\""
               "/usr/bin/${program} links ${lib}, but Depends lacks ${pkg}: ${depends}")
    endforeach()
endforeach()

# 5. The installed executables run from the scratch root against the system's Qt.
set(env "${CMAKE_COMMAND}" -E env --unset=LD_LIBRARY_PATH)
run("learnid-cli scenario --print" ${env} "${root}/usr/bin/learnid-cli" scenario --print)
string(JSON lambda ERROR_VARIABLE json_error GET "${OUT}" controller lambda)
expect("NOT json_error" "scenario --print is not the scenario JSON (${json_error}):\n${OUT}")
run("learnid-cli run --iterations 2" ${env} "${root}/usr/bin/learnid-cli" run --iterations 2)
expect("OUT MATCHES \"\\n *2 \"" "learnid-cli run --iterations 2 printed no row 2:\n${OUT}")
foreach(program IN LISTS PROGRAMS)  # every executable starts from the package
    run("${program} --version" ${env} "${root}/usr/bin/${program}" --version)
    expect("OUT MATCHES \"${program} ${VERSION}\"" "${program} --version printed '${OUT}'")
endforeach()
message(STATUS "the package installs and runs: ${PROGRAMS}")
