# Link-time optimisation of the simulated tick (docs/engine.md, "Speed").
#
# A tick runs through many small functions of several core modules (the
# positioner, its servo loops, the PLC, the plant). The modules on that path
# are compiled with GCC's LTO information as well as their machine code
# ("fat" objects); `k528` and the engine benchmark link them with -flto, so a
# tick is optimised across modules as one program. Every other program (the
# tests among them) links the same objects' machine code as before, at no
# extra link time. Release builds with GCC only; K528_LTO=OFF turns it off.
option(K528_LTO "Link k528 and the engine benchmark with link-time optimisation (GCC, Release)" ON)

set(K528_LTO_MODULES units catalog axis engine plc machine)
set(K528_LTO_ACTIVE OFF)
if(K528_LTO AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_BUILD_TYPE MATCHES "^(Release|RelWithDebInfo)$")
    set(K528_LTO_ACTIVE ON)
endif()

# GCC's linker plugin optimises LTO information at any link that finds it,
# unless told not to: every program links the machine code (-fno-lto) but
# those of k528_lto_link() (target property K528_LTO_LINK).
if(K528_LTO_ACTIVE)
    add_link_options("$<$<NOT:$<BOOL:$<TARGET_PROPERTY:K528_LTO_LINK>>>:-fno-lto>")
endif()

# A core module on the tick's path: LTO information besides the machine code.
function(k528_lto_module target)
    if(K528_LTO_ACTIVE)
        target_compile_options(${target} PRIVATE -flto=auto -ffat-lto-objects)
    endif()
endfunction()

# A program whose speed is the tick's: linked with link-time optimisation.
function(k528_lto_link target)
    if(K528_LTO_ACTIVE)
        set_target_properties(${target} PROPERTIES K528_LTO_LINK ON)
        target_compile_options(${target} PRIVATE -flto=auto)
        # GCC 12 reports a false -Wstringop-overflow inside std::string's
        # operator+ once it is inlined across modules (GCC bug 105651, the
        # same false positive app/cli silences for -Wrestrict).
        target_link_options(${target} PRIVATE -flto=auto -Wno-stringop-overflow)
    endif()
endfunction()
