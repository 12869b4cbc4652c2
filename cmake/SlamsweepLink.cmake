# Every function and datum in its own section, and lld drops the sections a program never reaches
# (--gc-sections). A batched library's object (CMake unity build) is linked whole; without this a program would
# keep its neighbours' code and load their shared libraries at start-up. GNU ld decides which shared libraries
# a program needs before it drops sections, lld after, so only lld keeps the lean programs lean.
find_program(SLAMSWEEP_LLD ld.lld)
if(NOT SLAMSWEEP_LLD)
  message(FATAL_ERROR "ld.lld not found: install Debian's lld package (scripts/install-deps.sh --build does)")
endif()
add_compile_options(-ffunction-sections -fdata-sections)
add_link_options(-fuse-ld=lld LINKER:--gc-sections)
