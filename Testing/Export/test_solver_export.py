"""Solver hand-off end to end: a VolGrid mesh written as gmsh 4.1 and 2.2, SU2, Medit, TetGen and an
OpenFOAM case, CGNS and Exodus II, each read back by a reader VolGrid did not write (meshio, gmsh's API,
OpenFOAM's checkMesh, cgns-convert's cgnscheck, ParaView's CGNS and Exodus readers),
which must report the same points, tets and patch names with the same face counts; OpenFOAM's
potentialFoam runs on the case; VolGrid Quality's non-orthogonality and skewness match checkMesh's; Medit,
gmsh, SU2, TetGen, OpenFOAM, CGNS and Exodus files read and written again are identical; bad requests fail cleanly. Usage: test_solver_export.py VOLGRID WORKDIR wing|onera [DATA_ROOT]
Exit 77 (skip) when the ONERA M6 domain is missing (a clone without ../shared/data/real)."""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import solver_readers as R  # noqa: E402

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(volgrid, *args, expect=0):
    p = subprocess.run([volgrid] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    print("$ volgrid " + " ".join(args) + "\n" + p.stdout + p.stderr, end="")
    if expect is not None and p.returncode != expect:
        raise SystemExit("volgrid %s: exit %d, expected %d" % (args[0], p.returncode, expect))
    return p


def mesh_case(volgrid, work, case, data_root):
    """Meshes the case into WORK/domain.mesh; returns the expected patch names and the `volgrid mesh`
    input and options that made it."""
    if case == "wing":
        stl = os.path.join(HERE, "..", "Data", "straight_wing.stl")
        run(volgrid, "prep", stl, os.path.join(work, "domain.vtk"), "--enclosure", "sphere",
            "--enclosure-scale", "10")
        report = run(volgrid, "mesh", os.path.join(work, "domain.vtk"), os.path.join(work, "domain.mesh"), "--json")
        return {"straight_wing", "farfield"}, [os.path.join(work, "domain.vtk")], json.loads(report.stdout)
    src = os.path.join(data_root, "derived-onera-m6", "onera_m6_halfsphere_domain.mesh")
    if not os.path.exists(src):
        print("SKIP: %s is missing (the real corpus ../shared/data/real is not on this machine)" % src)
        raise SystemExit(SKIP)
    # Refs of the CAD faces: 1 the far-field sphere, 2 the symmetry plane y = 0, 3..12 the wing.
    patches = ["--patch", "farfield=1,symmetry=2,wing=3,4,5,6,7,8,9,10,11,12"]
    report = run(volgrid, "mesh", src, os.path.join(work, "domain.mesh"), *patches, "--json")
    return {"wing", "symmetry", "farfield"}, [src] + patches, json.loads(report.stdout)


def write_potential_case(case):
    """The few dictionaries checkMesh and potentialFoam need: free-stream velocity and reference pressure at
    the far field, slip walls."""
    def put(rel, cls, body):
        path = os.path.join(case, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write("FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n    object %s;\n}\n%s\n"
                    % (cls, os.path.basename(rel), body))
    with open(os.path.join(case, "constant", "polyMesh", "boundary")) as f:
        text = f.read()
    names = [n for n in ("farfield", "symmetry", "wing", "straight_wing") if "\n    %s\n" % n in text]
    def field(value, by_name):
        return "dimensions %s;\ninternalField uniform %s;\nboundaryField\n{\n%s}\n" % (
            value[0], value[1], "".join("    %s { %s }\n" % (n, by_name(n)) for n in names))
    u = lambda n: ("type fixedValue; value uniform (1 0 0);" if n == "farfield" else
                   "type symmetryPlane;" if n == "symmetry" else "type slip;")
    p = lambda n: ("type fixedValue; value uniform 0;" if n == "farfield" else
                   "type symmetryPlane;" if n == "symmetry" else "type zeroGradient;")
    put("0/U", "volVectorField", field(("[0 1 -1 0 0 0 0]", "(0 0 0)"), u))
    put("0/p", "volScalarField", field(("[0 2 -2 0 0 0 0]", "0"), p))
    put("system/controlDict", "dictionary", "application potentialFoam;\nstartFrom startTime;\nstartTime 0;\n"
        "stopAt endTime;\nendTime 1;\ndeltaT 1;\nwriteControl timeStep;\nwriteInterval 1;\nwriteFormat ascii;\n")
    put("system/fvSchemes", "dictionary", "ddtSchemes { default steadyState; }\ngradSchemes { default Gauss linear; }\n"
        "divSchemes { default none; }\nlaplacianSchemes { default Gauss linear limited 0.5; }\n"
        "interpolationSchemes { default linear; }\nsnGradSchemes { default limited 0.5; }\n")
    put("system/fvSolution", "dictionary", "solvers\n{\n    Phi { solver PCG; preconditioner DIC; tolerance 1e-06; "
        "relTol 0.01; }\n}\npotentialFlow\n{\n    nNonOrthogonalCorrectors 2;\n    PhiRefCell 0;\n    PhiRefValue 0;\n}\n")


def main():
    volgrid, work, case = sys.argv[1], sys.argv[2], sys.argv[3]
    data_root = sys.argv[4] if len(sys.argv) > 4 else ""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    expected_names, mesh_input, mesh_report = mesh_case(volgrid, work, case, data_root)
    w = lambda name: os.path.join(work, name)
    for out, extra in (("mesh.msh", []), ("mesh22.msh", ["--format", "gmsh22"]), ("mesh.su2", []),
                       ("mesh.node", []), ("case", ["--format", "openfoam"]), ("again.mesh", []),
                       ("mesh.cgns", []), ("mesh.exo", [])):
        run(volgrid, "convert", w("domain.mesh"), w(out), *extra)

    # The reference: gmsh's own API on the 4.1 file (names and face counts per physical group).
    points, tets, faces = R.gmsh_api(w("mesh.msh"))
    print("gmsh API: %d points, %d tets, patches %s" % (points, tets, faces))
    check(set(faces) == expected_names, "gmsh API sees the patches %s" % sorted(expected_names))
    check(tets > 0 and all(n > 0 for n in faces.values()), "every patch has faces")
    check(R.gmsh_api(w("mesh22.msh")) == (points, tets, faces), "gmsh API on the 2.2 file: same")
    check(R.meshio_gmsh(w("mesh.msh")) == (points, tets, faces), "meshio on the 4.1 file: same")
    check(R.meshio_gmsh(w("mesh22.msh")) == (points, tets, faces), "meshio on the 2.2 file: same")
    check(R.meshio_su2(w("mesh.su2")) == (points, tets, sum(faces.values())), "meshio on the SU2 file: same counts")
    with open(w("mesh.su2")) as f:
        markers = [l.split("=", 1)[1].strip() for l in f if l.startswith("MARKER_TAG=")]
    check(sorted(markers) == sorted(expected_names), "SU2 has one MARKER_TAG per patch")
    check(R.meshio_tetgen(w("mesh.node")) == (points, tets), "meshio on the TetGen files: same counts")
    medit = R.meshio_medit(w("domain.mesh"), {})
    check(medit[:2] == (points, tets) and sorted(medit[2].values()) == sorted(faces.values()),
          "meshio on the Medit file: same counts, same faces per ref")

    code, out = R.cgnscheck(w("mesh.cgns"))
    check(code == 0 and "ERROR" not in out.upper().replace("0 ERRORS", ""), "cgnscheck: the CGNS file is valid")
    check(R.paraview_reader("cgns", w("mesh.cgns")) == (points, tets, faces),
          "ParaView's CGNS reader: same points, tets, patch names and faces (one BC per patch)")
    check(R.paraview_reader("exodus", w("mesh.exo")) == (points, tets, faces),
          "ParaView's Exodus II reader: same points, tets, side set names and faces")
    check(R.meshio_exodus(w("mesh.exo")) == (points, tets), "meshio on the Exodus II file: same counts")

    write_potential_case(w("case"))
    foam = R.check_mesh(w("case"))
    print("checkMesh: points %d cells %d patches %s max non-orthogonality %s, %d faces > 70 deg, max skewness %s"
          % (foam["points"], foam["cells"], foam["patches"], foam["max_non_orthogonality"], foam["severe_faces"],
             foam["max_skewness"]))
    if not foam["ok"]:
        print(foam["output"])
    out = foam["output"]
    topology = out.split("Checking topology...", 1)[-1].split("Checking patch topology", 1)[0]
    check(all(t in topology for t in ("Boundary definition OK.", "Upper triangular ordering OK.", "Face vertices OK.",
                                      "Number of regions: 1 (OK).")) and "***" not in topology,
          "OpenFOAM checkMesh: topology OK (boundary definition, upper triangular ordering, one region)")
    check("Boundary openness" in out and "Max cell openness" in out and "openness" not in
          "".join(l for l in out.splitlines() if l.lstrip().startswith("***")),
          "OpenFOAM checkMesh: closed boundary and cells (openness OK)")
    if case == "onera":
        check(foam["ok"], "OpenFOAM checkMesh: Mesh OK")
    check((foam["points"], foam["cells"], foam["patches"]) == (points, tets, faces),
          "checkMesh: same points, cells, patch names and faces")
    # VolGrid Quality's CFD metrics (Core/Quality/CfdQuality.h) against checkMesh's on the same mesh.
    q = json.loads(run(volgrid, "quality", w("domain.mesh"), "--json").stdout)
    print("VolGrid quality: max non-orthogonality %.6g, %d faces > 70 deg, max skewness %.6g, max volume ratio %.6g"
          % (q["MaxNonOrthogonality"], q["SevereNonOrthogonalFaces"], q["MaxSkewness"], q["MaxVolumeRatio"]))
    check(abs(q["MaxNonOrthogonality"] - foam["max_non_orthogonality"]) <= 0.1,
          "VolGrid Quality's max non-orthogonality matches checkMesh's within 0.1 deg")
    check(q["SevereNonOrthogonalFaces"] == foam["severe_faces"], "same number of faces above 70 deg as checkMesh")
    # The mesher's own count after its orthogonality moves (OrthogonalitySmoothing.h) is what a solver sees,
    # and the moves did not add any.
    print("volgrid mesh: %d faces > 70 deg (%d before its %d orthogonality moves)"
          % (mesh_report["nonortho_severe_faces"], mesh_report["nonortho_severe_before_moves"],
             mesh_report["nonortho_moves"]))
    check(mesh_report["nonortho_severe_faces"] == foam["severe_faces"],
          "volgrid mesh --json counts the faces above 70 deg that checkMesh counts")
    check(mesh_report["nonortho_severe_faces"] <= mesh_report["nonortho_severe_before_moves"],
          "the orthogonality moves never add a severe face")
    check(abs(q["MaxSkewness"] - foam["max_skewness"]) <= 0.01 * foam["max_skewness"],
          "VolGrid Quality's max skewness matches checkMesh's within 1%")
    # An OpenFOAM case lists each face's vertices in another order: the same figures up to the last bit.
    for other in ("mesh.cgns", "mesh.exo", "case"):
        q2 = json.loads(run(volgrid, "quality", w(other), "--json").stdout)
        check(q2["SevereNonOrthogonalFaces"] == q["SevereNonOrthogonalFaces"] and
              all(abs(q2[k] - q[k]) <= 1e-12 * abs(q[k]) for k in ("MaxNonOrthogonality", "MaxSkewness")),
              "volgrid quality on %s: the same CFD figures as on the Medit file" % other)
    code, out = R.foam(w("case"), "potentialFoam")
    if code != 0 or "\nEnd" not in out:
        print(out[-3000:])
    check(code == 0 and "\nEnd" in out, "OpenFOAM potentialFoam runs to completion")

    with open(w("domain.mesh"), "rb") as a, open(w("again.mesh"), "rb") as b:
        check(a.read() == b.read(), "Medit written, read back and written again: identical")
    run(volgrid, "convert", w("again.mesh"), w("again.msh"))
    with open(w("mesh.msh"), "rb") as a, open(w("again.msh"), "rb") as b:
        check(a.read() == b.read(), "gmsh file from the re-read Medit file: identical")

    for src, dst, extra in (("mesh.msh", "again41.msh", []), ("mesh22.msh", "again22.msh", ["--format", "gmsh22"]),
                            ("mesh.su2", "again.su2", [])):
        run(volgrid, "convert", w(src), w(dst), *extra)
        with open(w(src), "rb") as a, open(w(dst), "rb") as b:
            check(a.read() == b.read(), "%s written, read back and written again: identical" % src)
    run(volgrid, "convert", w("mesh.exo"), w("again.exo"))
    with open(w("mesh.exo"), "rb") as a, open(w("again.exo"), "rb") as b:
        check(a.read() == b.read(), "Exodus II written, read back and written again: identical")
    # HDF5 stamps each object with its creation time, so two CGNS files of the same mesh differ in bytes:
    # cgnsdiff compares every node and its data; the Medit file from the re-read CGNS file must be the original.
    run(volgrid, "convert", w("mesh.cgns"), w("again.cgns"))
    p = subprocess.run(["cgnsdiff", "-d", w("mesh.cgns"), w("again.cgns")], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    check(p.returncode == 0 and p.stdout.strip() == "", "CGNS written, read back and written again: identical nodes and data")
    run(volgrid, "convert", w("again.cgns"), w("from-cgns.mesh"))
    with open(w("domain.mesh"), "rb") as a, open(w("from-cgns.mesh"), "rb") as b:
        check(a.read() == b.read(), "Medit file from the re-read CGNS file: identical to the original")
    run(volgrid, "convert", w("case"), w("case-again"), "--format", "openfoam")
    same = True
    for f in ("points", "faces", "owner", "neighbour", "boundary"):
        with open(w("case/constant/polyMesh/" + f), "rb") as a, open(w("case-again/constant/polyMesh/" + f), "rb") as b:
            same = same and a.read() == b.read()
    check(same, "OpenFOAM polyMesh written, read back and written again: identical")
    run(volgrid, "convert", w("mesh.node"), w("again.node"))
    same = True
    for ext in (".node", ".ele", ".face"):
        with open(w("mesh" + ext), "rb") as a, open(w("again" + ext), "rb") as b:
            same = same and a.read() == b.read()
    check(same, "TetGen files written, read back and written again: identical")
    # `volgrid mesh IN OUT.<ext>` writes every format itself: the same files as the conversions above
    # (the mesh is deterministic; CGNS compared node by node, HDF5 stamps times).
    for out, extra in (("mesh.msh", []), ("mesh22.msh", ["--format", "gmsh22"]), ("mesh.su2", []),
                       ("mesh.node", []), ("case", ["--format", "openfoam"]), ("mesh.cgns", []), ("mesh.exo", [])):
        direct = "direct-" + out
        run(volgrid, "mesh", mesh_input[0], w(direct), *(mesh_input[1:] + extra))
        if out == "case":
            same = all(open(w("case/constant/polyMesh/" + f), "rb").read() ==
                       open(w(direct + "/constant/polyMesh/" + f), "rb").read()
                       for f in ("points", "faces", "owner", "neighbour", "boundary"))
        elif out == "mesh.cgns":
            p = subprocess.run(["cgnsdiff", "-d", w(out), w(direct)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True)
            same = p.returncode == 0 and p.stdout.strip() == ""
        else:
            exts = (".node", ".ele", ".face") if out == "mesh.node" else ("",)
            same = all(open(w(out[:-5] + e if e else out), "rb").read() ==
                       open(w(direct[:-5] + e if e else direct), "rb").read() for e in exts)
        check(same, "volgrid mesh ... %s: the same mesh as the conversion" % direct)

    if case == "wing":
        # OBJ groups become named patches (a tet whose faces are in two `g` groups, one of them twice).
        with open(w("groups.obj"), "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ng wing upper\nf 1 3 2\nf 1 2 4\ng tip\nf 1 4 3\n"
                    "g wing upper\nf 2 3 4\n")
        run(volgrid, "mesh", w("groups.obj"), w("groups.msh"), "--no-field-points")
        check(R.gmsh_api(w("groups.msh"))[2] == {"wing upper": 3, "tip": 1}, "OBJ groups are named patches")
        # OBJ objects too (Blender writes `o` and no `g`); a `g` inside an object names the faces after it.
        with open(w("objects.obj"), "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\no Wing\nf 1 3 2\nf 1 2 4\no Tip\nf 1 4 3\n"
                    "g Tip_cap\nf 2 3 4\n")
        run(volgrid, "mesh", w("objects.obj"), w("objects.msh"), "--no-field-points")
        check(R.gmsh_api(w("objects.msh"))[2] == {"Wing": 2, "Tip": 1, "Tip_cap": 1}, "OBJ objects are named patches")
    bad = run(volgrid, "convert", w("domain.mesh"), w("out.xyz"), expect=2)
    check(not os.path.exists(w("out.xyz")) and "extension" in bad.stderr, "unknown extension: clear error, no file")
    bad = run(volgrid, "convert", w("domain.mesh"), w("case"), "--format", "openfoam", expect=1)
    check("already exists" in bad.stderr and os.path.exists(w("case/0/U")), "existing case directory: refused, untouched")
    bad = run(volgrid, "convert", w("domain.mesh"), w("badcase"), "--format", "openfoam", "--patch", "bad;name=1",
              expect=1)
    check("OpenFOAM word" in bad.stderr and not os.path.exists(w("badcase")), "bad OpenFOAM word: clear error, no case")
    bad = run(volgrid, "convert", w("domain.mesh"), w("missing-dir/out.msh"), expect=1)
    check("missing-dir/out.msh" in bad.stderr and "No such file" in bad.stderr and not os.listdir(work).count("missing-dir"),
          "unwritable path: names the path and the reason")
    check(not [f for f in os.listdir(work) if "volgrid-tmp" in f], "no temporary file left behind")
    if failures:
        print("%d check(s) failed" % len(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
