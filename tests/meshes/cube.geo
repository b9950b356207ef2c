// Unit cube of tetrahedra for verification tests; -setnumber h <size> sets the element size.
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.35 ];
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Mesh.Algorithm3D = 1;
Physical Volume("domain") = {1};
Physical Surface("left") = {1};
Physical Surface("right") = {2};
Physical Surface("front") = {3};
Physical Surface("back") = {4};
Physical Surface("bottom") = {5};
Physical Surface("top") = {6};
