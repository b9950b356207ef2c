// A box whose volume's physical name holds a blank: its options (-thin film_young) cannot be given.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.CharacteristicLengthMax = 0.5;
Physical Volume("thin film") = {1};
e = 1e-6;
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 1 + e, 1 + e, e};
