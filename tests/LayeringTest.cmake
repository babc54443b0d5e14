# cmake -DROOT=<source dir> -P LayeringTest.cmake: what the include paths cannot catch. Each core
# library sees only its own and its linked libraries' headers (cmake/Layering.cmake), and its
# include path has no Widgets, Gui or Charts folder; but Qt's parent include folder, which
# Qt6::Core brings, would still resolve a module-qualified <QtWidgets/QWidget>. No core file may
# name such a header.
file(GLOB_RECURSE sources "${ROOT}/core/*.h" "${ROOT}/core/*.cpp")
set(found)
foreach(file IN LISTS sources)
    file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*<Qt(Widgets|Gui|Charts|OpenGL|Svg|PrintSupport)/")
    foreach(line IN LISTS lines)
        file(RELATIVE_PATH rel "${ROOT}" "${file}")
        list(APPEND found "${rel}: ${line}")
    endforeach()
endforeach()
list(LENGTH sources count)
if(found)
    list(JOIN found "\n" found)
    message(FATAL_ERROR "core/ must not include GUI modules:\n${found}")
endif()
message(STATUS "layering: ${count} core files include no Widgets, Gui or Charts header")
