"""Level 3a components: geometry with ``netgen.occ`` and the FEM steps in Exudyn (paper section 2.3).

Two groups, as in the paper: geometry (primitives, extrusion of a face, booleans, moving and
rotating, fillets, chamfers, named faces) and FEM (mesh with a hard-coded ``maxh``, import into
Exudyn's ``FEMinterface`` with material and interfaces, Hurty-Craig-Bampton modes, eigenfrequencies).
Every example is a complete part program in the style of the ground truths in
``meceng.tasks.parts``; ``tests/test_catalog_part.py`` runs the geometry examples and one FEM example.
"""

from __future__ import annotations

from meceng.catalog.component import Component, text_block
from meceng.tasks.part_base import PART_PREAMBLE, STEEL, fem_block


def _geometry(code: str) -> str:
    return f"{PART_PREAMBLE}\n{text_block(code)}\n"


def _part(code: str, interfaces: tuple[str, ...] = ("left", "right"), maxh: float = 0.02) -> str:
    return f"{PART_PREAMBLE}\n{text_block(code)}\n\n{fem_block(maxh, STEEL, interfaces)}"


_BEAM = """
    shape = Box(Pnt(0, -0.02, -0.01), Pnt(0.5, 0.02, 0.01))
    shape.faces.Min(X).name = 'left'
    shape.faces.Max(X).name = 'right'
"""

BOX = Component(
    name="Box",
    description="cuboid solid between two corner points (plates, blocks, bars, feet)",
    context=text_block("""
        shape = Box(Pnt(x0, y0, z0), Pnt(x1, y1, z1))
        - Axis-aligned cuboid between the corner with the smallest and the one with the largest coordinates.
        - A box centred at c with size (a, b, h): Box(Pnt(cx-a/2, cy-b/2, cz-h/2), Pnt(cx+a/2, cy+b/2, cz+h/2)).
        - Place it directly in the frame of the description (the grader does not align parts).
    """),
    example=_geometry("""
        # a 0.2 x 0.1 x 0.05 m block with its bottom face centre at the origin
        shape = Box(Pnt(-0.1, -0.05, 0), Pnt(0.1, 0.05, 0.05))
    """),
    group="part",
)

CYLINDER = Component(
    name="Cylinder",
    description="circular cylinder solid along an axis (shafts, pins, bores, discs, knuckles, towers)",
    context=text_block("""
        shape = Cylinder(Pnt(x, y, z), axisDirection, r=radius, h=length)
        - Pnt is the centre of the start face; axisDirection is X, Y, Z or Vec(dx, dy, dz); the cylinder
          extends by h along the direction.
        - A bore or hole is a cylinder subtracted from a solid (BooleanCut). A hole the description calls
          through must span the whole wall: start the cylinder on one surface with h = the wall thickness, or
          start it outside the wall and make it longer; both cut the same hole. A hole that is not through
          gets exactly its depth as h.
    """),
    example=_geometry("""
        # a shaft of radius 0.02 m and length 0.3 m along x, starting at the origin
        shape = Cylinder(Pnt(0, 0, 0), X, r=0.02, h=0.3)
    """),
    group="part",
)

SPHERE = Component(
    name="Sphere",
    description="sphere solid (balls, spherical ends, counterweights)",
    context=text_block("""
        shape = Sphere(Pnt(x, y, z), r=radius)
    """),
    example=_geometry("""
        shape = Sphere(Pnt(0, 0, 0.1), r=0.05)
    """),
    group="part",
)

EXTRUDE = Component(
    name="Extrude",
    description=(
        "a planar face (rectangle, circle, polygon drawn on a work plane) extruded to a solid; profiles, "
        "keyways, ribs, L-shapes; can also make boxes and cylinders"
    ),
    context=text_block("""
        wp = WorkPlane(Axes((x0, y0, z0), n=normal, h=xDirectionOfPlane))
        face = wp.Rectangle(a, b).Face()        # corner at the plane origin, a along h, b along n x h
        face = wp.Circle(u, v, r).Face()        # circle centred at plane coordinates (u, v)
        face = wp.MoveTo(u0, v0).LineTo(u1, v1).LineTo(u2, v2).Close().Face()   # polygon
        solid = face.Extrude(h)                  # along the plane normal n
        - Axes((x0, y0, z0), n=Z, h=X) is the xy-plane at height z0: plane coordinates (u, v) = (x - x0, y - y0).
        - Rectangle(a, b) starts at the plane origin (it is not centred): move the origin with MoveTo or put
          the Axes origin at the corner.
        - Extrude along -n by giving the work plane the opposite normal.
    """),
    example=_geometry("""
        # an L-shaped profile in the xz-plane, extruded 0.1 m along y
        wp = WorkPlane(Axes((0, 0, 0), n=-Y, h=X))
        profile = wp.MoveTo(0, 0).LineTo(0.2, 0).LineTo(0.2, 0.02).LineTo(0.02, 0.02).LineTo(0.02, 0.15) \\
            .LineTo(0, 0.15).Close().Face()
        shape = profile.Extrude(0.1)
    """),
    group="part",
)

BOOLEAN_FUSE = Component(
    name="BooleanFuse",
    description="union of two solids into one part (shaft with disc, plate with feet, leaf with knuckle)",
    context=text_block("""
        shape = solidA + solidB
        - The solids must touch or overlap; the result is one solid whose coplanar faces may be merged.
        - Name interface faces only after all booleans: fusing and cutting create new faces and drop names.
    """),
    example=_geometry("""
        # a shaft with a disc in its middle
        shaft = Cylinder(Pnt(0, 0, 0), X, r=0.02, h=0.4)
        disc = Cylinder(Pnt(0.18, 0, 0), X, r=0.1, h=0.04)
        shape = shaft + disc
    """),
    group="part",
)

BOOLEAN_CUT = Component(
    name="BooleanCut",
    description="subtract one solid from another (bores, holes, keyways, slots, grooves, hollow profiles)",
    context=text_block("""
        shape = solidA - solidB
        - A through hole: subtract a cylinder that spans at least the whole wall (see Cylinder).
        - A keyway: extrude the keyway's base face and subtract the extruded solid from the shaft.
    """),
    example=_geometry("""
        # a block with a bore of radius 0.02 m along x through its middle
        block = Box(Pnt(0, -0.05, 0), Pnt(0.04, 0.05, 0.1))
        shape = block - Cylinder(Pnt(0, 0, 0.06), X, r=0.02, h=0.04)
    """),
    group="part",
)

TRANSFORM = Component(
    name="Transform",
    description="translate or rotate a solid (place repeated features, tilt a part into the stated frame)",
    context=text_block("""
        moved = solid.Move((dx, dy, dz))                       # translation, returns a new shape
        turned = solid.Rotate(Axis((x, y, z), direction), angleInDegrees)   # rotation about an axis
        - Both return a new solid; the original is unchanged. Angles are in DEGREES.
        - Copies of a feature at several positions: create it once, Move() it, fuse or cut each copy.
    """),
    example=_geometry("""
        # two holes 0.1 m apart in a plate: one hole cylinder, moved for the second hole
        plate = Box(Pnt(0, 0, 0), Pnt(0.3, 0.1, 0.01))
        hole = Cylinder(Pnt(0.1, 0.05, 0), Z, r=0.01, h=0.01)
        shape = plate - hole - hole.Move((0.1, 0, 0))
        shape = shape.Rotate(Axis((0, 0, 0), Z), 90)
    """),
    group="part",
)

FILLET = Component(
    name="Fillet",
    description="round edges of a solid with a given radius",
    context=text_block("""
        shape = shape.MakeFillet(edges, r)
        - edges: a list of edges, e.g. shape.edges.Max(Z) (one edge), [e for e in shape.edges if ...], or a
          filtered list such as shape.edges[X > 0.1]; select exactly the edges the description names.
        - A fillet removes (1 - pi/4) r^2 of cross section per unit edge length. Name faces afterwards.
    """),
    example=_geometry("""
        # a bar with its four long edges (along x) rounded with r = 0.004 m
        bar = Box(Pnt(0, -0.02, -0.01), Pnt(0.5, 0.02, 0.01))
        longEdges = [e for e in bar.edges if abs(e.bounding_box[1][0] - e.bounding_box[0][0]) > 0.4]
        shape = bar.MakeFillet(longEdges, 0.004)
    """),
    group="part",
)

CHAMFER = Component(
    name="Chamfer",
    description="bevel edges of a solid with a given distance (45 degree chamfers)",
    context=text_block("""
        shape = shape.MakeChamfer(edges, d)
        - edges: list of the edges to bevel (see Fillet for selecting edges); d: chamfer distance on both faces.
        - A chamfer removes d^2 / 2 of cross section per unit edge length. Name faces afterwards.
    """),
    example=_geometry("""
        # a block with the four top edges chamfered by 0.005 m
        block = Box(Pnt(-0.05, -0.05, 0), Pnt(0.05, 0.05, 0.04))
        topEdges = [e for e in block.edges if e.center.z > 0.04 - 1e-9]
        shape = block.MakeChamfer(topEdges, 0.005)
    """),
    group="part",
)

NAMED_FACES = Component(
    name="NamedFaces",
    description="give faces names; the named faces are the part's interfaces (joints, supports, loads)",
    context=text_block("""
        shape.faces.Min(X).name = 'left'            # face with the smallest x (also Max, Y, Z)
        shape.faces.Nearest(Pnt(x, y, z)).name = 'bore'   # face closest to a point (e.g. on a bore surface)
        for f in shape.faces: ...                   # f.center, f.mass (area), f.bounding_box to test faces
        - Name faces AFTER all booleans, fillets and chamfers (they create new faces).
        - An interface may consist of several faces with the same name (e.g. both halves of a bore).
        - The names must be exactly the interface names of the description; they become boundary names
          of the mesh (boundaryNamesList of ImportMeshToFEM).
    """),
    example=_geometry("""
        shape = Box(Pnt(0, -0.02, -0.01), Pnt(0.5, 0.02, 0.01)) - Cylinder(Pnt(0.25, 0, -0.01), Z, r=0.005, h=0.02)
        shape.faces.Min(X).name = 'left'
        shape.faces.Max(X).name = 'right'
        shape.faces.Nearest(Pnt(0.255, 0, 0)).name = 'hole'
    """),
    group="part",
)

GENERATE_MESH = Component(
    name="GenerateMesh",
    description="tetrahedral finite element mesh of the solid with a hard-coded maximum element size maxh",
    context=text_block("""
        mesh = ngs.Mesh(OCCGeometry(shape).GenerateMesh(maxh=0.01))
        - Hard-code maxh as a number literal in the call (the value given in the description). Programs
          without a literal maxh are not run.
        - Needs `import ngsolve as ngs` and `from netgen.occ import *`.
    """),
    example=_part(_BEAM),
    group="part",
)

IMPORT_MESH = Component(
    name="ImportMeshToFEM",
    description="import the mesh into Exudyn's FEMinterface with material (E, nu, rho) and the interfaces",
    context=text_block("""
        from exudyn.FEM import FEMinterface
        fem = FEMinterface()
        fem.ImportMeshFromNGsolve(mesh, density=rho, youngsModulus=E, poissonsRatio=nu, meshOrder=1,
                                  boundaryNamesList=['left', 'right'])
        - boundaryNamesList: the interface names in the order of the description; each becomes a node set
          (without the list every boundary, also unnamed ones, becomes a node set).
        - density in kg/m^3, youngsModulus in Pa; meshOrder=1 (linear tetrahedra).
        - fem.GetRigidBodyInertia().Mass() is the part's mass.
    """),
    example=_part(_BEAM),
    dependencies=("GenerateMesh",),
    group="part",
)

HCB_MODES = Component(
    name="HCBModes",
    description="Hurty-Craig-Bampton reduction with static modes at the interfaces and eigenmodes",
    context=text_block("""
        from exudyn.FEM import HCBstaticModeSelection
        boundaryNodes, boundaryWeights = fem.GetBoundaryNodeSetsAsLists()
        fem.ComputeHurtyCraigBamptonModes(boundaryNodesList=boundaryNodes, nEigenModes=6,
                                          boundaryNodesWeights=boundaryWeights,
                                          computationMode=HCBstaticModeSelection.RBE2)
        - GetBoundaryNodeSetsAsLists() returns the node lists and weights of the interfaces in the order of
          boundaryNamesList.
        - nEigenModes: number of fixed-interface eigenmodes (at least 6).
    """),
    example=_part(_BEAM),
    dependencies=("ImportMeshToFEM",),
    group="part",
)

EIGENFREQUENCIES = Component(
    name="EigenFrequencies",
    description="eigenfrequencies of the reduced part in Hz (to check the part)",
    context=text_block("""
        frequencies = fem.GetEigenFrequenciesHz()   # after ComputeHurtyCraigBamptonModes
    """),
    example=_part(_BEAM) + "frequencies = fem.GetEigenFrequenciesHz()\n",
    dependencies=("HCBModes",),
    group="part",
)

GEOMETRY = (BOX, CYLINDER, SPHERE, EXTRUDE, BOOLEAN_FUSE, BOOLEAN_CUT, TRANSFORM, FILLET, CHAMFER, NAMED_FACES)
FEM = (GENERATE_MESH, IMPORT_MESH, HCB_MODES, EIGENFREQUENCIES)
COMPONENTS = GEOMETRY + FEM
