// Lets a library folder build before it has sources of its own (CMake needs one source file).
namespace candela::detail { int emptyTranslationUnit = 0; }
