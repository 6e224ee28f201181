// volgrid: the command-line face of VolGrid. `volgrid help` lists the sub-commands.
#include "Commands.h"

#include <csignal>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <cstdio>
#include <cstring>
#include <new>
#include <string>

int runRefineCommand(int argc, char** argv); // RefineCommand.cxx: volgrid refine MESH.vtu OUT.vtu --size-array NAME

namespace
{
struct SubCommand
{
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

const SubCommand kCommands[] = {
  { "delaunay", runDelaunayCommand,
    "INPUT.node | --random N [--seed S]  [--check] [--json] [--out FILE.vtu]: Delaunay tetrahedralization" },
  { "mesh", runMeshCommand,
    "SURFACE OUT.vtu|.msh|.su2|.mesh [--format openfoam] [--patch NAME=ID,...] [--json] [--boundary OUT.vtp] [--check] "
    "[--alpha A ...]: boundary-conforming volume mesh" },
  { "refine", runRefineCommand,
    "MESH.vtu OUT.vtu --size-array NAME [--alpha A] [--json]: refine a tet mesh to a target size (adaptivity)" },
  { "quality", runQualityCommand, "MESH.vtu [--json] [--bins N]: volume or surface grid quality summary" },
  { "prep", runPrepCommand,
    "IN... OUT [--enclosure box|sphere|...] [--enclosure-scale S] [--json]: repair, orient, enclose surfaces" },
  { "convert", runConvertCommand,
    "IN OUT [--format NAME] [--patch NAME=ID,...]: a tet mesh to gmsh, SU2, OpenFOAM, Medit or TetGen" },
  { "check", runCheckCommand, "SURFACE [--json]: surface diagnostics (exit 0 clean, 1 defects)" },
};

int printUsage(FILE* out)
{
  std::fprintf(out, "usage: volgrid COMMAND [ARGS]\n\ncommands:\n");
  for (const SubCommand& c : kCommands)
  {
    std::fprintf(out, "  %-9s %s\n", c.name, c.summary);
  }
  return out == stderr ? 2 : 0;
}
} // namespace

int main(int argc, char** argv)
{
  // Past a file size limit (ulimit -f), write() then fails with EFBIG and the writers report it, instead of
  // the process being killed by SIGXFSZ with a cut temporary file.
  std::signal(SIGXFSZ, SIG_IGN);
#if defined(__GLIBC__)
  // The mesh's arrays grow by reallocation; glibc's default raises its mmap threshold each time such a
  // block is freed, so later blocks come from the heap, whose freed space stays in the process. A fixed
  // 1 MB threshold hands every large block back on free: peak RSS of `volgrid mesh` on the ONERA M6
  // domain 210 -> 191 MB at 1M tets and 726 -> 688 MB at 5.3M, for about 2% more time in the kernel.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  if (argc < 2)
  {
    return printUsage(stderr);
  }
  const std::string command = argv[1];
  if (command == "help" || command == "--help" || command == "-h")
  {
    return printUsage(stdout);
  }
  for (const SubCommand& c : kCommands)
  {
    if (command == c.name)
    {
      try
      {
        return c.run(argc - 1, argv + 1);
      }
      catch (const std::bad_alloc&)
      {
        std::fprintf(stderr,
                     "volgrid %s: out of memory (the size estimate did not foresee this run: try a coarser "
                     "size or --max-tets, and please report the command)\n",
                     c.name);
        return 3;
      }
      catch (const std::exception& e)
      {
        std::fprintf(stderr,
                     "volgrid %s: internal error: %s (a bug: please report it with the command and the "
                     "input file)\n",
                     c.name, e.what());
        return 3;
      }
    }
  }
  std::fprintf(stderr, "volgrid: unknown command '%s'\n", command.c_str());
  return printUsage(stderr);
}
