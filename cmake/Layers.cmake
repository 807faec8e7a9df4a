# SPDX-License-Identifier: MIT
# One static library per folder of cmake/layers.txt (see there). For a folder F the target is F with
# '/' replaced by '_' (core/base -> core_base, widgets/map -> widgets_map, app/cli -> app_cli).
#
# Each target compiles F's *.cpp and *.h (not those of subfolders) and gets, as its include path,
# a view: a folder of symbolic links to F and to every folder F may use, directly or through
# another. core folders appear under their own name ("config/bridgeconfig.h"), others under their
# path ("widgets/map/mappage.h", "app/cli/clioutput.h"). So a header of a folder F may not use is
# not found: the include fails to compile.
#
# Libraries of its own: Qt and yaml-cpp (their types appear in our headers) are public; Paho,
# qt6keychain, roscpp and rosbag are private to the folder that wraps them.

set(BRIDGESCOPE_LAYERS_FILE "${CMAKE_CURRENT_LIST_DIR}/layers.txt")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${BRIDGESCOPE_LAYERS_FILE}")

# bridgescope_read_layers(): sets BRIDGESCOPE_LAYERS (folders, lowest first) and, per folder F,
# BRIDGESCOPE_LAYER_USES_<target> and BRIDGESCOPE_LAYER_LIBS_<target>.
function(bridgescope_layer_target folder out)
    string(REPLACE "/" "_" t "${folder}")
    set(${out} "${t}" PARENT_SCOPE)
endfunction()

macro(bridgescope_read_layers)
    set(BRIDGESCOPE_LAYERS "")
    file(STRINGS "${BRIDGESCOPE_LAYERS_FILE}" _lines)
    foreach(_line IN LISTS _lines)
        string(REGEX REPLACE "#.*" "" _line "${_line}")
        string(STRIP "${_line}" _line)
        if(_line STREQUAL "")
            continue()
        endif()
        # Columns are separated by two or more spaces; lists inside a column by one.
        string(REGEX REPLACE "[ ][ ]+" ";" _cols "${_line}")
        list(LENGTH _cols _n)
        if(NOT _n EQUAL 3)
            message(FATAL_ERROR "${BRIDGESCOPE_LAYERS_FILE}: want 3 columns: ${_line}")
        endif()
        list(GET _cols 0 _folder)
        list(GET _cols 1 _uses)
        list(GET _cols 2 _libs)
        bridgescope_layer_target("${_folder}" _t)
        string(REPLACE " " ";" _uses "${_uses}")
        string(REPLACE " " ";" _libs "${_libs}")
        list(REMOVE_ITEM _uses "-")
        list(REMOVE_ITEM _libs "-")
        foreach(_u IN LISTS _uses)
            if(NOT _u IN_LIST BRIDGESCOPE_LAYERS)
                message(FATAL_ERROR "${BRIDGESCOPE_LAYERS_FILE}: ${_folder} uses ${_u}, which is not listed above it")
            endif()
        endforeach()
        list(APPEND BRIDGESCOPE_LAYERS "${_folder}")
        set(BRIDGESCOPE_LAYER_USES_${_t} "${_uses}")
        set(BRIDGESCOPE_LAYER_LIBS_${_t} "${_libs}")
    endforeach()
endmacro()

# The folders `folder` may use, directly or through others (itself excluded).
function(bridgescope_layer_closure folder out)
    bridgescope_layer_target("${folder}" t)
    set(result "")
    foreach(u IN LISTS BRIDGESCOPE_LAYER_USES_${t})
        bridgescope_layer_closure("${u}" sub)
        list(APPEND result "${u}" ${sub})
    endforeach()
    list(REMOVE_DUPLICATES result)
    set(${out} "${result}" PARENT_SCOPE)
endfunction()

# bridgescope_add_layer(FOLDER [EXCLUDE file...]): the library of one folder of the table.
function(bridgescope_add_layer folder)
    cmake_parse_arguments(L "" "" "EXCLUDE" ${ARGN})
    bridgescope_layer_target("${folder}" t)
    file(GLOB sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/${folder}/*.cpp" "${PROJECT_SOURCE_DIR}/${folder}/*.h")
    foreach(x IN LISTS L_EXCLUDE)
        list(REMOVE_ITEM sources "${PROJECT_SOURCE_DIR}/${folder}/${x}")
    endforeach()
    add_library(${t} STATIC ${sources})

    set(view "${CMAKE_BINARY_DIR}/layer-views/${t}")
    # Links from an earlier configure go first (one by one: never recurse into a link to sources).
    file(GLOB old LIST_DIRECTORIES true "${view}/*" "${view}/widgets/*" "${view}/app/*")
    foreach(o IN LISTS old)
        if(IS_SYMLINK "${o}")
            file(REMOVE "${o}")
        endif()
    endforeach()
    bridgescope_layer_closure("${folder}" visible)
    foreach(f IN ITEMS "${folder}" ${visible})
        string(REGEX REPLACE "^core/" "" name "${f}")
        get_filename_component(parent "${view}/${name}" DIRECTORY)
        file(MAKE_DIRECTORY "${parent}")
        file(CREATE_LINK "${PROJECT_SOURCE_DIR}/${f}" "${view}/${name}" SYMBOLIC)
    endforeach()
    target_include_directories(${t} PUBLIC "${view}")

    foreach(u IN LISTS BRIDGESCOPE_LAYER_USES_${t})
        bridgescope_layer_target("${u}" ut)
        target_link_libraries(${t} PUBLIC ${ut})
    endforeach()
    target_link_libraries(${t} PUBLIC bridgescope_options)
    foreach(lib IN LISTS BRIDGESCOPE_LAYER_LIBS_${t})
        if(lib MATCHES "^Qt6::" OR lib STREQUAL "yaml-cpp")
            target_link_libraries(${t} PUBLIC ${lib})
        else()
            target_link_libraries(${t} PRIVATE ${lib})
        endif()
    endforeach()
endfunction()

# Every folder of the table whose first part is `top` (core, widgets, app).
function(bridgescope_add_layers top)
    cmake_parse_arguments(L "" "" "EXCLUDE" ${ARGN})
    foreach(folder IN LISTS BRIDGESCOPE_LAYERS)
        if(folder MATCHES "^${top}/")
            bridgescope_add_layer("${folder}" EXCLUDE ${L_EXCLUDE})
        endif()
    endforeach()
endfunction()
