#pragma once
/// \file
/// Header-only or compiled. By default every function of pgm is defined in its header, so that an
/// `#include` is all a program needs (CMake: pgm::core). Linked to pgm::pgm, a program is compiled
/// with PGM_SEPARATE_COMPILATION: the headers then only declare the library's larger functions,
/// whose definitions (impl/*.ipp beside each header) libpgm holds compiled once, and a translation
/// unit compiles its own code and the templates it instantiates, not the library again.
///
/// One program, one way: every part of it links pgm::pgm, or none does.

#if defined(PGM_SEPARATE_COMPILATION)
#define PGM_DECL
#else
#define PGM_DECL inline
#endif
