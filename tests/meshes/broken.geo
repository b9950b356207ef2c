SetFactory("OpenCASCADE");
// A syntax error on purpose: the bad_geo test checks that gmsh's failure is reported.
Box(1) = {0, 0, 0, 1, 1, 1
