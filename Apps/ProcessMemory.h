// How the command-line program (and the benchmarks, which time what it does) ask the C library
// to keep freed memory for reuse.
#ifndef foldingmeshes_ProcessMemory_h
#define foldingmeshes_ProcessMemory_h

namespace foldingmeshes
{
namespace cli
{
/**
 * Freed memory stays in the process for the next allocation instead of going back to the
 * system (glibc: mallopt with a 32 MB mmap threshold, a 512 MB trim threshold and a 64 MB top
 * pad; elsewhere nothing). A fold allocates and frees the same large arrays over and over
 * (face trees, distances, work meshes): given back, each comes back as fresh pages, and every
 * first touch of a page is a page fault - 14,800 of them on the chair's compress, 10,700 kept
 * (0.90 -> 0.86 s). For a process that exits when its one job is done; a library must not
 * change this for the program it runs in (ParaView, Python), so the filters never call it.
 */
void KeepFreedMemoryForReuse();
}
}

#endif
