"""`volgrid mesh --orthogonality-first` as a finite-volume solver sees it: the same domain meshed with and
without the flag, each written as an OpenFOAM case, both checked exactly (--check) and by OpenFOAM's
checkMesh. With the flag checkMesh must count at most half of the severely non-orthogonal faces (> 70 deg)
it counts without it, its count must be the one `volgrid mesh --json` reports, and the mesh must keep
checkMesh's topology checks. On the ONERA M6 domain the flag's mesh must also have no more severe faces
than TetGen's (-pYq1.414) and Gmsh HXT's meshes of the same domain (issue 16, acceptance 6). Cases: the
bundled straight wing in the demo's sphere (wing), the ONERA M6 half-sphere domain of the real corpus
(onera; exit 77 when ../shared is absent).
Usage: test_orthogonality_first.py VOLGRID WORKDIR wing|onera [DATA_ROOT]"""
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import solver_readers as R  # noqa: E402
from test_solver_export import write_potential_case  # noqa: E402

SKIP = 77
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(volgrid, *args):
    p = subprocess.run([volgrid] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    print("$ volgrid " + " ".join(args) + "\n" + p.stderr, end="")
    if p.returncode != 0:
        raise SystemExit("volgrid %s: exit %d\n%s" % (args[0], p.returncode, p.stdout))
    return p.stdout


def must(*cmd):
    p = subprocess.run(list(cmd), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        raise SystemExit("%s failed:\n%s" % (" ".join(cmd), p.stdout[-2000:]))


def other_engines(volgrid, domain, work, options):
    """checkMesh's severe faces of TetGen's -pYq1.414 and Gmsh HXT's meshes of the Medit domain."""
    w = lambda name: os.path.join(work, name)
    shutil.copyfile(domain, w("dom.mesh"))
    must("tetgen", "-pYq1.414", w("dom.mesh"))
    must(volgrid, "convert", w("dom.1.node"), w("tetgen"), "--format", "openfoam", *options)
    must(volgrid, "prep", w("dom.mesh"), w("gmsh.stl"))
    with open(w("gmsh.geo"), "w") as g:
        g.write('Merge "%s";\nSurface Loop(1) = Surface{:};\nVolume(1) = {1};\n' % w("gmsh.stl"))
    must("gmsh", "-3", "-algo", "hxt", w("gmsh.geo"), "-save_all", "-format", "msh41", "-o", w("gmsh.msh"))
    must(volgrid, "convert", w("gmsh.msh"), w("gmsh"), "--format", "openfoam")
    faces = {}
    for engine, case in (("TetGen", w("tetgen")), ("Gmsh HXT", w("gmsh"))):
        write_potential_case(case)
        foam = R.check_mesh(case)
        print("%s: checkMesh %d cells, %d faces > 70 deg" % (engine, foam["cells"], foam["severe_faces"]))
        check(foam["cells"] > 0, "%s's mesh read by checkMesh" % engine)
        faces[engine] = foam["severe_faces"]
    return faces


def main():
    volgrid, work, case = sys.argv[1], sys.argv[2], sys.argv[3]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    w = lambda name: os.path.join(work, name)
    if case == "wing":
        domain = w("domain.vtp")
        run(volgrid, "prep", os.path.join(HERE, "..", "Data", "straight_wing.stl"), domain, "--enclosure", "sphere",
            "--enclosure-scale", "5")
        options = []
    else:
        domain = os.path.join(sys.argv[4], "derived-onera-m6", "onera_m6_halfsphere_domain.mesh")
        if not os.path.exists(domain):
            print("SKIP: %s is missing (the real corpus ../shared/data/real is not on this machine)" % domain)
            raise SystemExit(SKIP)
        options = ["--patch", "farfield=1,symmetry=2,wing=3,4,5,6,7,8,9,10,11,12"]
    severe = {}
    for label, flags in (("default", []), ("orthogonality-first", ["--orthogonality-first"])):
        report = json.loads(run(volgrid, "mesh", domain, w(label), "--format", "openfoam", "--check", "--json",
                                *options, *flags))
        write_potential_case(w(label))
        foam = R.check_mesh(w(label))
        out = foam["output"]
        print("%s: %d cells, dihedral %.2f..%.2f deg; checkMesh: %d faces > 70 deg, max non-orthogonality %s, "
              "max skewness %s, %s" % (label, foam["cells"], report["min_dihedral"], report["max_dihedral"],
                                       foam["severe_faces"], foam["max_non_orthogonality"], foam["max_skewness"],
                                       "Mesh OK" if foam["ok"] else "not OK"))
        check(report["boundary_preserved"] and report["volume_relative_error"] <= 1e-9,
              "%s: boundary and volume exact" % label)
        check(foam["cells"] == report["tets"], "%s: checkMesh reads every tet" % label)
        topology = out.split("Checking topology...", 1)[-1].split("Checking patch topology", 1)[0]
        check(all(t in topology for t in ("Boundary definition OK.", "Upper triangular ordering OK.",
                                          "Face vertices OK.")) and "***" not in topology,
              "%s: checkMesh topology OK" % label)
        check(foam["severe_faces"] == report["nonortho_severe_faces"],
              "%s: checkMesh's severe faces (%d) are the ones volgrid reports (%d)"
              % (label, foam["severe_faces"], report["nonortho_severe_faces"]))
        severe[label] = foam["severe_faces"]
    check(severe["orthogonality-first"] <= 0.5 * severe["default"],
          "--orthogonality-first: checkMesh's severe faces %d <= 1/2 of the default's %d"
          % (severe["orthogonality-first"], severe["default"]))
    if case == "onera":
        for engine, faces in other_engines(volgrid, domain, work, options).items():
            check(severe["orthogonality-first"] <= faces,
                  "--orthogonality-first: checkMesh's severe faces %d <= %s's %d" % (severe["orthogonality-first"],
                                                                                   engine, faces))
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
