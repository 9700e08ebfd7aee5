# Profile-guided optimisation of the simulated tick (docs/engine.md,
# "Speed").
#
# The modules a tick runs through (K528_LTO_MODULES: units, catalog, axis,
# engine, plc, machine) are optimised with a profile of their own run: the
# build first makes a sub-build (<build>/pgo) that compiles them instrumented
# (-fprofile-generate), links bench/pgo_train.cpp and runs it once (the
# sample programs on their machines, the engine benchmark's program, an idle
# machine); the profile it leaves in <build>/pgo/profile then guides GCC here
# (-fprofile-use: which branches are taken, what to inline, the cold paths
# out of the way). What the code computes does not change (no -ffast-math:
# the results are bit for bit the same, test machine.trace_golden); only how
# fast. A change of a tick module's source, or of the trainer, builds and
# runs the trainer again and recompiles the modules with the new profile.
#
# Release builds with GCC only (with LTO or without); K528_PGO=OFF turns it
# off. K528_PGO_GENERATE is the sub-build's own switch.
option(K528_PGO "Optimise the tick's modules with a profile of their run (GCC, Release)" ON)
set(K528_PGO_GENERATE "" CACHE PATH
    "Internal, the sub-build of K528_PGO: instrument the tick's modules, profile into this folder")
mark_as_advanced(K528_PGO_GENERATE)

set(K528_PGO_ACTIVE OFF)
if(K528_PGO_GENERATE)
    set(K528_PGO_MODE generate)
elseif(K528_PGO AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_BUILD_TYPE MATCHES "^(Release|RelWithDebInfo)$")
    set(K528_PGO_MODE use)
    set(K528_PGO_ACTIVE ON)
else()
    set(K528_PGO_MODE off)
endif()

# The profile (a folder of .gcda files) and a stamp touched after each
# training run, which the tick modules' objects depend on.
if(K528_PGO_MODE STREQUAL "generate")
    set(K528_PGO_DIR "${K528_PGO_GENERATE}")
else()
    set(K528_PGO_DIR "${PROJECT_BINARY_DIR}/pgo/profile")
endif()
set(K528_PGO_STAMP "${K528_PGO_DIR}.stamp")

if(K528_PGO_MODE STREQUAL "generate")
    # The trainer and nothing else is linked here (bench/CMakeLists.txt).
    add_link_options(-fprofile-generate)
elseif(K528_PGO_MODE STREQUAL "use")
    include(ExternalProject)
    set(pgo_args
        -DCMAKE_BUILD_TYPE=Release
        -DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}
        -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
        -DK528_PGO=OFF
        -DK528_LTO=OFF
        -DK528_PGO_GENERATE=${K528_PGO_DIR}
        -DK528_BUILD_GUI=OFF
        -DK528_BUILD_TESTS=OFF
        -DK528_BUILD_BENCH=ON
        -DK528_USE_CCACHE=${K528_USE_CCACHE})
    ExternalProject_Add(k528_pgo
        SOURCE_DIR "${PROJECT_SOURCE_DIR}"
        BINARY_DIR "${PROJECT_BINARY_DIR}/pgo"
        CMAKE_GENERATOR "${CMAKE_GENERATOR}"
        CMAKE_ARGS ${pgo_args}
        # The sub-build's own dependencies decide what is rebuilt and whether
        # the trainer runs again (k528_pgo_profile in bench/CMakeLists.txt).
        BUILD_COMMAND ${CMAKE_COMMAND} --build <BINARY_DIR> --target k528_pgo_profile
        BUILD_ALWAYS ON
        BUILD_BYPRODUCTS "${K528_PGO_STAMP}"
        INSTALL_COMMAND ""
        USES_TERMINAL_BUILD ON)
endif()

# A core module on the tick's path: instrumented in the sub-build, optimised
# with the profile here.
function(k528_pgo_module target)
    if(K528_PGO_MODE STREQUAL "generate")
        target_compile_options(${target} PRIVATE
            "-fprofile-generate=${K528_PGO_DIR}"
            "-fprofile-prefix-path=${PROJECT_BINARY_DIR}"
            -fprofile-update=single)
    elseif(K528_PGO_MODE STREQUAL "use")
        # The profile names each object by its path below the build folder,
        # the same here as in the sub-build. Functions the trainer never ran
        # are optimised as without a profile; a profile that no longer fits a
        # changed function is left out for it (never happens in a build: the
        # stamp below brings a new one first).
        target_compile_options(${target} PRIVATE
            "-fprofile-use=${K528_PGO_DIR}"
            "-fprofile-prefix-path=${PROJECT_BINARY_DIR}"
            -fprofile-partial-training
            -Wno-missing-profile
            -Wno-coverage-mismatch)
        add_dependencies(${target} k528_pgo)
        get_target_property(sources ${target} SOURCES)
        set_source_files_properties(${sources} TARGET_DIRECTORY ${target}
            PROPERTIES OBJECT_DEPENDS "${K528_PGO_STAMP}")
        # ccache would not know the profile is an input.
        set_target_properties(${target} PROPERTIES CXX_COMPILER_LAUNCHER "")
    endif()
endfunction()
