"""OpenFOAM checkMesh's CFD figures (max non-orthogonality, faces above 70 deg, max skewness, verdict) for
the ONERA M6 half-sphere domain meshed by VolGrid at default settings and with --orthogonality-first,
TetGen -pYq1.414 and Gmsh HXT, each mesh turned into an OpenFOAM case by `volgrid convert`. A report, not a test (nothing asserted).
Usage: python3 bench_checkmesh.py VOLGRID WORKDIR DOMAIN.mesh"""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Export"))
import solver_readers as R  # noqa: E402
from test_solver_export import write_potential_case  # noqa: E402

PATCHES = ["--patch", "farfield=1,symmetry=2,wing=3,4,5,6,7,8,9,10,11,12"]


def must(*cmd):
    p = subprocess.run(list(cmd), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        raise SystemExit("%s failed:\n%s" % (" ".join(cmd), p.stdout[-2000:]))
    return p.stdout


def report(engine, case):
    write_potential_case(case)
    f = R.check_mesh(case)
    print("%-30s %s points %d cells %d patches %s | max non-orthogonality %s, faces > 70 deg %d, max skewness %s"
          % (engine, "Mesh OK    " if f["ok"] else "Mesh NOT OK", f["points"], f["cells"], f["patches"],
             f["max_non_orthogonality"], f["severe_faces"], f["max_skewness"]))


def main():
    volgrid, work, domain = sys.argv[1], sys.argv[2], sys.argv[3]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    w = lambda name: os.path.join(work, name)
    shutil.copyfile(domain, w("dom.mesh"))
    must(volgrid, "mesh", w("dom.mesh"), w("volgrid"), "--format", "openfoam", *PATCHES)
    report("VolGrid (default)", w("volgrid"))
    must(volgrid, "mesh", w("dom.mesh"), w("volgrid_orth"), "--format", "openfoam", "--orthogonality-first", *PATCHES)
    report("VolGrid --orthogonality-first", w("volgrid_orth"))
    # TetGen keeps the Medit refs as face markers.
    must("tetgen", "-pYq1.414", w("dom.mesh"))
    must(volgrid, "convert", w("dom.1.node"), w("tetgen"), "--format", "openfoam", *PATCHES)
    report("TetGen -pYq1.414", w("tetgen"))
    # Gmsh HXT from an STL of the same surface (one patch: gmsh's STL import has no refs).
    must(volgrid, "prep", w("dom.mesh"), w("gmsh.stl"))
    with open(w("gmsh.geo"), "w") as g:
        g.write('Merge "%s";\nSurface Loop(1) = Surface{:};\nVolume(1) = {1};\n' % w("gmsh.stl"))
    must("gmsh", "-3", "-algo", "hxt", w("gmsh.geo"), "-save_all", "-format", "msh41", "-o", w("gmsh.msh"))
    must(volgrid, "convert", w("gmsh.msh"), w("gmsh"), "--format", "openfoam")
    report("Gmsh HXT", w("gmsh"))


if __name__ == "__main__":
    main()
