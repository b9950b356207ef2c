// A film (z in [0.7, 1]) bonded to a substrate (z in [0, 0.7]), tetrahedra; two volume regions.
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.2 ];
Box(1) = {0, 0, 0, 1, 1, 0.7};
Box(2) = {0, 0, 0.7, 1, 1, 0.3};
Coherence;
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Physical Volume("substrate") = {1};
Physical Volume("film") = {2};
e = 1e-6;
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
Physical Surface("top") = Surface In BoundingBox{-e, -e, 1 - e, 1 + e, 1 + e, 1 + e};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, 1 + e, 1 + e};
Physical Surface("front") = Surface In BoundingBox{-e, -e, -e, 1 + e, e, 1 + e};
