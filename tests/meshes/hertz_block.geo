// A quarter block [0, L] x [0, L] x [-L, 0] of hexahedra, refined towards the indentation point
// (the origin) by geometric progression r: the element next to it is L (r - 1) / (r^N - 1).
// -setnumber L <nm> -setnumber N <cells per edge> -setnumber r <ratio>
DefineConstant[ L = 5000, N = 24, r = 1.2 ];
Point(1) = {0, 0, 0};  Point(2) = {L, 0, 0};  Point(3) = {L, L, 0};  Point(4) = {0, L, 0};
Point(5) = {0, 0, -L}; Point(6) = {L, 0, -L}; Point(7) = {L, L, -L}; Point(8) = {0, L, -L};
// edges oriented away from the origin's corner, so every progression refines towards it
Line(1) = {1, 2}; Line(2) = {4, 3}; Line(3) = {5, 6}; Line(4) = {8, 7};    // along x
Line(5) = {1, 4}; Line(6) = {2, 3}; Line(7) = {5, 8}; Line(8) = {6, 7};    // along y
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8}; // along -z
Curve Loop(1) = {1, 6, -2, -5};   Plane Surface(1) = {1};  // top z = 0
Curve Loop(2) = {3, 8, -4, -7};   Plane Surface(2) = {2};  // bottom
Curve Loop(3) = {1, 10, -3, -9};  Plane Surface(3) = {3};  // front y = 0
Curve Loop(4) = {2, 11, -4, -12}; Plane Surface(4) = {4};  // back y = L
Curve Loop(5) = {5, 12, -7, -9};  Plane Surface(5) = {5};  // left x = 0
Curve Loop(6) = {6, 11, -8, -10}; Plane Surface(6) = {6};  // right x = L
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};
Transfinite Curve{1:12} = N + 1 Using Progression r;
Transfinite Surface{1:6};
Recombine Surface{1:6};
Transfinite Volume{1};
Physical Volume("domain") = {1};
Physical Surface("top") = {1};
Physical Surface("bottom") = {2};
Physical Surface("front") = {3};
Physical Surface("back") = {4};
Physical Surface("left") = {5};
Physical Surface("right") = {6};
