# Exact expectations per canonical model, shared by the MeshLab 2020.09 tests (tests/meshlab) and
# the MeshLab 2025.07 tests (tests/meshlab2025): both APIs must give the same results.
# _detect_<model>: expected `mlcheck report` of the model file; _repair_<model>: of the repaired
# layer MeshLab saved. Only for the models DESIGN.md section 4 gives numbers for; every model in
# resources/models also gets the generic checks (lossless, MeshLab finds it manifold,
# defect layer == core).
set(_detect_twocubes singular_edges=1 singular_edge_contenders=4 boundary_edges=0 singular_vertices=2)
set(_repair_twocubes vertices=16 faces=24 components=2 boundary_edges=0 watertight=1)
set(_detect_hourglass singular_edges=0 pinch_vertices=1 boundary_edges=0)
set(_repair_hourglass vertices=8 faces=8 components=2 boundary_edges=0)
set(_detect_bowtie singular_edges=0 pinch_vertices=1)
set(_repair_bowtie vertices=6 faces=2 components=2)
set(_detect_book_of_three singular_edges=1 singular_edge_contenders=3)
set(_repair_book_of_three faces=3)
set(_repair_plate_box_rib components=2 boundary_edges=0)
# prisms24 has 48 triangles and 72 quads (120 faces for the core); MeshLab triangulates the quads
# on loading, so its layer has 192 triangles, all of which must survive.
set(_detect_prisms24 faces=120 triangles=192 boundary_edges=0)
set(_repair_prisms24 faces=192 components=24 boundary_edges=0 watertight=1)
