# Bad input and -help (included by tests/CMakeLists.txt). Every bad input ends with one line,
# "indent: error: <message naming the option, region or file>", and a non-zero exit (tests/expect_error.sh;
# the table of cases and messages is in doc/testing.md, "Bad input"). The checks of a running load program
# (no contact by the end of loading, contact at the surface's edge, inverted cells, A(h_c) beyond the
# surface) are test_run_checks' (run_checks_*).
# Each is also a probe of the fault matrix (label faults, scripts/fault-matrix.py).
set(TEST_LABEL "input;faults")
set(EXPECT_ERROR ${CMAKE_CURRENT_SOURCE_DIR}/expect_error.sh)
set(OK_BOX -dm_plex_box_faces 2,2,2 -output_fields 0 -quiet)
set(INDENT $<TARGET_FILE:indent>)
set(INDENT_NP2 ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 $<TARGET_FILE:indent>)
set(BAD_DIR ${CMAKE_CURRENT_BINARY_DIR}/bad)
set(PAPER_GEO ${CMAKE_SOURCE_DIR}/inputs/berkovich_half.geo)
set(PAPER_COARSE -options_file ${CMAKE_SOURCE_DIR}/inputs/berkovich.opts -mesh_file ${PAPER_GEO}
  -mesh_geo_parameters h_tip=60,h_far=600,r_fine=200 -load_steps 2 -output_fields 0 -quiet)
set(SPHERE -bc_fixed bottom -indenter_type sphere -indenter_radius 1 -load_depth 0.1)

# Broken copies of good meshes (tests/make_bad_meshes.py).
add_custom_command(OUTPUT ${MESHDIR}/truncated.msh ${MESHDIR}/corrupt.msh ${MESHDIR}/ghost.msh ${MESHDIR}/lid.msh
  COMMAND ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/make_bad_meshes.py ${MESHDIR}/cube41.msh ${MESHDIR}/cube22.msh
  ${MESHDIR}
  DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/make_bad_meshes.py ${MESHDIR}/cube41.msh ${MESHDIR}/cube22.msh)
# A mesh partitioned by gmsh (-part), which PETSc's reader (3.18) does not take.
add_custom_command(OUTPUT ${MESHDIR}/partitioned.msh
  COMMAND ${GMSH_EXECUTABLE} -3 ${CMAKE_CURRENT_SOURCE_DIR}/meshes/cube.geo -setnumber h 0.35 -part 2 -format msh41
    -o ${MESHDIR}/partitioned.msh > /dev/null
  DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/meshes/cube.geo)
add_custom_target(bad_meshes ALL DEPENDS ${MESHDIR}/truncated.msh ${MESHDIR}/corrupt.msh ${MESHDIR}/ghost.msh
  ${MESHDIR}/lid.msh ${MESHDIR}/partitioned.msh)

# The longer messages, in pieces.
string(CONCAT RE_BAD_GEO "gmsh could not mesh '.*broken.geo' \\(-mesh_file\\): '.*broken.geo', line [0-9]+: "
  "syntax error .*: see '.*bad_geo/mesh.msh.log'")
string(CONCAT RE_LINEAR_SOLVES "failed 2 times in a row \\(last: Newton: DIVERGED_LINEAR_SOLVE.* the linear solves "
  "failed, which smaller steps do not cure: a direct solve \\(-ksp_type preonly")
string(CONCAT RE_UNKNOWN_PARAMETER "-mesh_geo_parameters: 'htip' is not a parameter of '.*berkovich_half.geo' "
  "\\(gmsh would ignore it\\). its parameters are: film, width, depth, h_tip, h_far, r_fine")
string(CONCAT RE_NEVER_TOUCHES "The indenter never touches the contact surface 'top': at the full depth "
  "\\(-load_depth 0.1 nm\\) its lowest point is at z = 1.9 nm")
string(CONCAT RE_THROUGH_BLOCK "-load_depth 2000 nm goes through the body: the indenter's lowest point would reach "
  "z = -2000 nm, at or below the mesh's bottom at z = -1500 nm \\(the body is 1500 nm thick")
string(CONCAT RE_ROTATION_HALF "-indenter_rotation 30 degrees: the berkovich indenter is not mirror-symmetric about "
  "the symmetry plane 'symmetry' \\(y = 0 nm, through its axis\\), so this half model does not represent it")
string(CONCAT RE_ROTATION_QUARTER "the berkovich indenter is not mirror-symmetric about the symmetry plane 'left' "
  "\\(x = 0 nm, through its axis\\), so this quarter model does not represent it. "
  "a three-sided pyramid has no two perpendicular mirror planes")

function(bad_np2 name)
  indent_script_test(${name} ${ARGN})
  set_tests_properties(${name} PROPERTIES PROCESSORS 2)
endfunction()

# ---- options whose values are out of range, missing or misspelt
# A word that is neither an option nor the value of the one before it (PETSc would skip it without a word): the
# second half of an unquoted list with a space.
string(CONCAT RE_STRAY "'h_far=600' after '-mesh_geo_parameters h_tip=60,' is not an option, and an option takes "
  "one value: quote a value that holds spaces")
indent_script_test(bad_stray_argument ${EXPECT_ERROR} "${RE_STRAY}"
  ${INDENT} ${PAPER_COARSE} -mesh_geo_parameters h_tip=60, h_far=600)
bad_np2(bad_stray_argument_np2 ${EXPECT_ERROR} "${RE_STRAY}"
  ${INDENT_NP2} ${PAPER_COARSE} -mesh_geo_parameters h_tip=60, h_far=600)
# An option written with '=' (PETSc takes it for an option of that whole name): said so, not "-domain_poisson is
# missing".
string(CONCAT RE_EQUALS "-domain_poisson=0.3: an option and its value are separated by a blank, not '=' "
  "\\(-domain_poisson 0.3\\)")
indent_script_test(bad_option_with_equals ${EXPECT_ERROR} "${RE_EQUALS}"
  ${INDENT} ${OK_BOX} -domain_young 100 -domain_poisson=0.3 -bc_fixed bottom)
bad_np2(bad_option_with_equals_np2 ${EXPECT_ERROR} "${RE_EQUALS}"
  ${INDENT_NP2} ${OK_BOX} -domain_young 100 -domain_poisson=0.3 -bc_fixed bottom)
indent_script_test(bad_stray_argument_op ${EXPECT_ERROR} "^indent-op: error: 'curve.csv' is not an option"
  $<TARGET_FILE:indent-op> curve.csv)
indent_script_test(bad_missing_mesh ${EXPECT_ERROR} "Mesh file 'nowhere.msh' \\(-mesh_file\\) does not exist"
  ${INDENT} -mesh_file nowhere.msh ${ELASTIC})
indent_script_test(bad_missing_region ${EXPECT_ERROR} "no surface named 'lid' \\(required by -bc_fixed\\)"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed lid)
indent_script_test(bad_missing_material ${EXPECT_ERROR} "option -domain_young \\(GPa\\) is missing"
  ${INDENT} ${OK_BOX} -bc_fixed bottom)
indent_script_test(bad_poisson ${EXPECT_ERROR} "-domain_poisson must lie in \\(-1, 0.5\\)"
  ${INDENT} ${OK_BOX} -domain_young 1 -domain_poisson 0.5)
indent_script_test(bad_formulation ${EXPECT_ERROR} "-formulation: 'large' is not one of small finite"
  ${INDENT} ${OK_BOX} -domain_young 1 -domain_poisson 0.3 -bc_fixed bottom -formulation large)
indent_script_test(bad_young ${EXPECT_ERROR} "-domain_young must be > 0"
  ${INDENT} ${OK_BOX} -domain_young -3 -domain_poisson 0.3)
indent_script_test(bad_unknown_option ${EXPECT_ERROR} "Unknown or unused option\\(s\\): -bc_fixd"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixd bottom)
indent_script_test(bad_degree ${EXPECT_ERROR} "-disc_degree must be 1 or 2"
  ${INDENT} ${OK_BOX} ${ELASTIC} -disc_degree 3)
indent_script_test(bad_roller ${EXPECT_ERROR} "-bc_roller: bad component 'w'"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_roller bottom:w)
indent_script_test(bad_plastic_missing_yield ${EXPECT_ERROR}
  "Region 'domain' is plastic \\(-domain_model plastic\\) but option -domain_yield"
  ${INDENT} ${OK_BOX} ${ELASTIC} -domain_model plastic -bc_fixed bottom)
indent_script_test(bad_plastic_yield ${EXPECT_ERROR} "-domain_yield must be > 0"
  ${INDENT} ${OK_BOX} ${PLASTIC} -domain_yield -1 -bc_fixed bottom)
# a stress in MPa: the region would never yield
indent_script_test(bad_plastic_yield_mpa ${EXPECT_ERROR}
  "The initial yield stress 300.? GPa \\(-domain_yield\\) is not below the region's Young's modulus 100.? GPa"
  ${INDENT} ${OK_BOX} ${PLASTIC} -domain_yield 300 -domain_saturation 500 -bc_fixed bottom)
indent_script_test(bad_swift_mpa ${EXPECT_ERROR}
  "yield stress 199.* GPa \\(-domain_swift_k and -domain_swift_eps0\\) is not below the region's Young's modulus"
  ${INDENT} ${OK_BOX} -domain_young 100 -domain_poisson 0.3 -domain_model plastic -domain_hardening swift
  -domain_swift_k 500 -domain_swift_eps0 0.01 -domain_hardening_exponent 0.2 -formulation small -bc_fixed bottom)
indent_script_test(bad_plastic_voce_rate ${EXPECT_ERROR} "-domain_voce_rate must be >= 0"
  ${INDENT} ${OK_BOX} ${PLASTIC} -domain_voce_rate -2 -bc_fixed bottom)
indent_script_test(bad_plastic_kinematic ${EXPECT_ERROR} "-domain_kinematic must be >= 0"
  ${INDENT} ${OK_BOX} ${PLASTIC} -domain_kinematic -2 -bc_fixed bottom)
indent_script_test(bad_model ${EXPECT_ERROR} "-domain_model: 'viscous' is not one of elastic plastic densifying"
  ${INDENT} ${OK_BOX} ${ELASTIC} -domain_model viscous -bc_fixed bottom)
indent_script_test(bad_hardening_law ${EXPECT_ERROR}
  "-domain_hardening: 'hollomon' is not one of voce linear power swift table"
  ${INDENT} ${OK_BOX} ${PLASTIC} -domain_hardening hollomon -bc_fixed bottom)
indent_script_test(bad_hardening_exponent ${EXPECT_ERROR} "-domain_hardening_exponent must lie in \\[0, 1\\]"
  ${INDENT} ${OK_BOX} -domain_young 100 -domain_poisson 0.3 -domain_model plastic -domain_yield 0.3
  -domain_hardening power -domain_hardening_exponent -0.1 -bc_fixed bottom)
indent_script_test(bad_hardening_table_missing ${EXPECT_ERROR} "-domain_hardening_file: cannot read 'nowhere.csv'"
  ${INDENT} ${OK_BOX} -domain_young 100 -domain_poisson 0.3 -domain_model plastic -domain_hardening table
  -domain_hardening_file nowhere.csv -bc_fixed bottom)
indent_script_test(bad_hardening_table_falling ${EXPECT_ERROR}
  "falling_curve.csv', line 4: the stress falls from 0.4 to 0.38 GPa. the curve must not fall"
  ${INDENT} ${OK_BOX} -domain_young 100 -domain_poisson 0.3 -domain_model plastic -domain_hardening table
  -domain_hardening_file ${CMAKE_CURRENT_SOURCE_DIR}/data/falling_curve.csv -bc_fixed bottom)
set(DENSIFYING -domain_young 72 -domain_poisson 0.17 -domain_model densifying -domain_yield 6 -bc_fixed bottom)
indent_script_test(bad_densifying_no_pressure ${EXPECT_ERROR}
  "Region 'domain' is densifying: option -domain_yield_pressure \\(GPa\\) is missing" ${INDENT} ${OK_BOX} ${DENSIFYING})
indent_script_test(bad_densifying_pressure ${EXPECT_ERROR} "-domain_yield_pressure must be > 0 \\(GPa\\), got -1"
  ${INDENT} ${OK_BOX} ${DENSIFYING} -domain_yield_pressure -1)
indent_script_test(bad_densifying_modulus ${EXPECT_ERROR} "-domain_densification_modulus must be >= 0 \\(GPa\\), got -5"
  ${INDENT} ${OK_BOX} ${DENSIFYING} -domain_yield_pressure 10 -domain_densification_modulus -5)
indent_script_test(bad_densifying_hardening_option ${EXPECT_ERROR} "Unknown or unused option\\(s\\): -domain_hardening"
  ${INDENT} ${OK_BOX} ${DENSIFYING} -domain_yield_pressure 10 -domain_hardening linear)
indent_script_test(bad_plastic_option_on_elastic ${EXPECT_ERROR} "Unknown or unused option\\(s\\): -domain_yield"
  ${INDENT} ${OK_BOX} ${ELASTIC} -domain_yield 0.3 -bc_fixed bottom)
indent_script_test(bad_load_cutback ${EXPECT_ERROR} "-load_cutback must lie in \\(0, 1\\)"
  ${INDENT} ${OK_BOX} ${ELASTIC} -load_cutback 1.5 -bc_fixed bottom)
indent_script_test(bad_op_file ${EXPECT_ERROR} "^indent-op: error: Cannot open the curve 'nowhere.csv' \\(-op_file\\)"
  $<TARGET_FILE:indent-op> -op_file nowhere.csv -indenter_type berkovich)
indent_script_test(bad_op_area_coefficients ${EXPECT_ERROR}
  "-op_area_coefficients give A\\(h_c\\) = 0.* an area must be > 0"
  $<TARGET_FILE:indent-op> -op_file ${CMAKE_CURRENT_SOURCE_DIR}/data/op_curve.csv -op_area_coefficients 0,0)
indent_script_test(bad_op_indenter_type ${EXPECT_ERROR}
  "^indent-op: error: -indenter_type: 'pyramid' is not one of sphere cone berkovich"
  $<TARGET_FILE:indent-op> -op_file nowhere.csv -indenter_type pyramid)
indent_script_test(bad_indenter_radius ${EXPECT_ERROR} "-indenter_type sphere needs -indenter_radius"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type sphere -load_depth 0.1)
indent_script_test(bad_indenter_depth ${EXPECT_ERROR} "-indenter_type needs the largest depth -load_depth"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone)
indent_script_test(bad_depth_without_indenter ${EXPECT_ERROR} "-load_depth needs an indenter: -indenter_type"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -load_depth 5)
indent_script_test(bad_friction ${EXPECT_ERROR} "-contact_friction must be >= 0"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone -load_depth 0.1 -contact_friction -0.1)
indent_script_test(bad_contact_surface ${EXPECT_ERROR} "no surface named 'lid' \\(required by -contact_surface\\)"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone -load_depth 0.1 -contact_surface lid)
indent_script_test(bad_contact_p2_tets ${EXPECT_ERROR} "Contact on P2 tetrahedra is not supported"
  ${INDENT} -mesh_file ${MESHDIR}/cube41.msh -disc_degree 2 -output_fields 0 -quiet ${ELASTIC} -bc_fixed bottom
  -indenter_type cone -load_depth 0.1)
indent_script_test(bad_indenter_angle ${EXPECT_ERROR} "-indenter_angle must lie in \\(0, 90\\) degrees"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone -indenter_angle 95 -load_depth 0.1)
indent_script_test(bad_unload_steps ${EXPECT_ERROR} "-load_unload_steps must be >= 1"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone -load_depth 0.1 -load_unload_steps 0)
indent_script_test(bad_output_fields_every ${EXPECT_ERROR} "-output_fields_every must be >= 1, got 0"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone -load_depth 0.1 -output_fields_every 0)
indent_script_test(bad_rho_scale ${EXPECT_ERROR} "-contact_rho_scale must be > 0, got -1"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone -load_depth 0.1 -contact_rho_scale -1)
indent_script_test(bad_sharp_rounding ${EXPECT_ERROR} "-indenter_sharp_rounding must be >= 0 \\(nm\\), got -1"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone -load_depth 0.1 -indenter_sharp_rounding -1)
indent_script_test(bad_stall_its ${EXPECT_ERROR} "-newton_stall_its must be >= 0"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -newton_stall_its -1)
indent_script_test(bad_pc_rebuild_cost ${EXPECT_ERROR} "-newton_pc_rebuild_cost must be >= 0, got -1"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -newton_pc_rebuild_cost -1)
indent_script_test(bad_op_fraction_indent ${EXPECT_ERROR} "-op_fraction must lie in \\(0, 1.?, got 2"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -indenter_type cone -load_depth 0.1 -op_fraction 2)

# ---- values that do not parse: the message names the option (and the unit)
indent_script_test(bad_depth_unit ${EXPECT_ERROR} "-load_depth: '60nm' is not a number \\(nm\\)"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -load_depth 60nm)
indent_script_test(bad_young_inf ${EXPECT_ERROR} "-domain_young: 'inf' is not a finite number \\(GPa\\)"
  ${INDENT} ${OK_BOX} -domain_young inf -domain_poisson 0.3 -bc_fixed bottom)
bad_np2(bad_young_nan_np2 ${EXPECT_ERROR} "-film_young: 'nan' is not a finite number \\(GPa\\)"
  ${INDENT_NP2} -mesh_file ${MESHDIR}/bilayer.msh ${OK_BOX} -film_young nan -film_poisson 0.3 -substrate_young 100
  -substrate_poisson 0.3)
indent_script_test(bad_young_overflow ${EXPECT_ERROR} "-domain_young: '1e400' is not a finite number \\(GPa\\)"
  ${INDENT} ${OK_BOX} -domain_young 1e400 -domain_poisson 0.3 -bc_fixed bottom)
indent_script_test(bad_friction_nan ${EXPECT_ERROR} "-contact_friction: 'nan' is not a finite number"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -contact_friction nan)
indent_script_test(bad_steps_not_integer ${EXPECT_ERROR} "-load_steps: '2.5' is not an integer"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -load_steps 2.5)
indent_script_test(bad_bool ${EXPECT_ERROR} "-contact_monitor: 'maybe' is not a boolean"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -contact_monitor maybe)
indent_script_test(bad_axis_count ${EXPECT_ERROR} "-indenter_axis needs two values x,y \\(nm\\), got 1"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -indenter_axis 0.5)
indent_script_test(bad_axis_value ${EXPECT_ERROR} "-indenter_axis: 'abc' in '0.5,abc' is not a number"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -indenter_axis 0.5,abc)
indent_script_test(bad_box_faces ${EXPECT_ERROR} "-dm_plex_box_faces: 'x' in '2,x,2' is not an integer"
  ${INDENT} ${ELASTIC} -bc_fixed bottom -output_fields 0 -dm_plex_box_faces 2,x,2)
indent_script_test(bad_bc_value_inf ${EXPECT_ERROR}
  "-bc_displacement: 'inf' for surface 'top' is not a finite number \\(nm\\)"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -bc_displacement top:z=inf)
indent_script_test(bad_petsc_real ${EXPECT_ERROR} "-snes_rtol: 'abc' is not a number"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -snes_rtol abc)
bad_np2(bad_petsc_type_np2 ${EXPECT_ERROR} "Unable to find requested KSP type foo"
  ${INDENT_NP2} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -ksp_type foo)

# ---- files: output directory, meshes, geometries
indent_script_test(bad_output_dir ${EXPECT_ERROR}
  "-output_dir '/proc/indent' cannot be|Cannot create or write to the output directory '/proc/indent'"
  ${INDENT} -dm_plex_box_faces 2,2,2 -quiet ${ELASTIC} -bc_fixed bottom -output_dir /proc/indent)
indent_script_test(bad_output_dir_is_file ${EXPECT_ERROR} --keep ${BAD_DIR}/a_file
  "-output_dir '.*a_file' (cannot be the output directory: it )?exists and is not a directory"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -output_fields 1 -output_dir ${BAD_DIR}/a_file)
bad_np2(bad_output_dir_parent_file_np2 ${EXPECT_ERROR} --keep ${BAD_DIR}/b_file
  "-output_dir '.*b_file/run' cannot be the output directory: '.*b_file' is not a directory"
  ${INDENT_NP2} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -output_dir ${BAD_DIR}/b_file/run)
# A mesh file that cannot be read, on 1 and 2 ranks. Rank 0 alone reads: on 2 ranks the line, then MPI_Abort.
function(bad_mesh_file name regex)
  indent_script_test(bad_msh_${name} ${EXPECT_ERROR} "${regex}"
    ${INDENT} -mesh_file ${MESHDIR}/${name}.msh ${ELASTIC} -bc_fixed bottom -output_fields 0)
  bad_np2(bad_msh_${name}_np2 ${EXPECT_ERROR} "${regex}"
    ${INDENT_NP2} -mesh_file ${MESHDIR}/${name}.msh ${ELASTIC} -bc_fixed bottom -output_fields 0)
endfunction()
bad_mesh_file(truncated "Mesh file '.*truncated.msh' \\(-mesh_file\\) is truncated or corrupt")
bad_mesh_file(corrupt "Cannot read mesh file '.*corrupt.msh' \\(-mesh_file\\): ")
bad_mesh_file(partitioned "Cannot read mesh file .*partitioned.msh. .-mesh_file.: it was partitioned by gmsh .-part.")
string(CONCAT RE_BLANK_NAME "Volume region 'thin film' cannot name options \\(-thin film_young\\): a volume's physical "
  "name may hold letters, digits, '_', '-' and '.'. rename it in the mesh \\(e.g. 'thin_film'\\)")
indent_script_test(bad_volume_name ${EXPECT_ERROR} --fresh ${CMAKE_CURRENT_BINARY_DIR}/bad_volume_name
  "${RE_BLANK_NAME}"
  ${INDENT} -mesh_file ${CMAKE_CURRENT_SOURCE_DIR}/meshes/blank_name.geo -bc_fixed bottom
  -output_dir ${CMAKE_CURRENT_BINARY_DIR}/bad_volume_name)
indent_script_test(bad_partitioner_blocks_with_file ${EXPECT_ERROR}
  "-mesh_partitioner blocks is for the built-in box. a mesh read from -mesh_file needs ptscotch, metis or simple"
  ${INDENT} -mesh_file ${MESHDIR}/cube41.msh ${ELASTIC} -mesh_partitioner blocks -bc_fixed bottom -output_fields 0)
indent_script_test(bad_empty_volume ${EXPECT_ERROR}
  "Volume region 'ghost' of mesh '.*ghost.msh' is empty: its physical volume has no cells"
  ${INDENT} -mesh_file ${MESHDIR}/ghost.msh ${ELASTIC} -ghost_young 1 -ghost_poisson 0.3 -bc_fixed bottom -output_fields
  0)
bad_np2(bad_empty_surface_np2 ${EXPECT_ERROR} "Surface 'lid' of mesh '.*lid.msh' \\(required by -bc_fixed\\) is empty"
  ${INDENT_NP2} -mesh_file ${MESHDIR}/lid.msh ${ELASTIC} -bc_fixed lid -output_fields 0)
indent_script_test(bad_empty_contact_surface ${EXPECT_ERROR}
  "Surface 'lid' of mesh '.*lid.msh' \\(required by -contact_surface\\) is empty"
  ${INDENT} -mesh_file ${MESHDIR}/lid.msh ${ELASTIC} ${SPHERE} -contact_surface lid -output_fields 0)
indent_script_test(bad_geo ${EXPECT_ERROR} --fresh ${CMAKE_CURRENT_BINARY_DIR}/bad_geo
  "${RE_BAD_GEO}"
  ${INDENT} -mesh_file ${CMAKE_CURRENT_SOURCE_DIR}/meshes/broken.geo -output_dir ${CMAKE_CURRENT_BINARY_DIR}/bad_geo
  ${ELASTIC})
# gmsh writes mesh.msh.tmp, renamed only on success: a failed run leaves an earlier mesh.msh as it was.
indent_script_test(bad_geo_keeps_mesh ${EXPECT_ERROR} --keep ${BAD_DIR}/keeps_mesh/mesh.msh
  "gmsh could not mesh '.*broken.geo' \\(-mesh_file\\)"
  ${INDENT} -mesh_file ${CMAKE_CURRENT_SOURCE_DIR}/meshes/broken.geo -output_dir ${BAD_DIR}/keeps_mesh -output_fields 0
  ${ELASTIC})
indent_script_test(bad_geo_parameters ${EXPECT_ERROR} "-mesh_geo_parameters needs a .geo -mesh_file"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -mesh_geo_parameters h_tip=5)
indent_script_test(bad_geo_parameter_syntax ${EXPECT_ERROR} "-mesh_geo_parameters: 'h_tip' is not name=value"
  ${INDENT} -mesh_file ${PAPER_GEO} -mesh_geo_parameters h_tip -output_dir ${CMAKE_CURRENT_BINARY_DIR}/bad_geo_syntax
  ${ELASTIC})
# Decided from the .geo's text before gmsh runs (which would ignore the name): nothing is written.
bad_np2(bad_geo_unknown_parameter_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/unknown_parameter --keep
  ${BAD_DIR}/unknown_parameter/notes.txt
  --absent ${BAD_DIR}/unknown_parameter/mesh.msh --absent ${BAD_DIR}/unknown_parameter/mesh.msh.log
  "${RE_UNKNOWN_PARAMETER}"
  ${INDENT_NP2} ${PAPER_COARSE} -mesh_geo_parameters htip=20 -output_dir ${BAD_DIR}/unknown_parameter)
# A misspelt option with a .geo: reported once, on 2 ranks, before gmsh runs (no mesh, no file written).
bad_np2(bad_option_before_gmsh_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/option_before_gmsh
  --absent ${BAD_DIR}/option_before_gmsh/mesh.msh --absent ${BAD_DIR}/option_before_gmsh/mesh.msh.log
  "Unknown or unused option\\(s\\): -film_yeld"
  ${INDENT_NP2} ${PAPER_COARSE} -film_yeld 0.3 -output_dir ${BAD_DIR}/option_before_gmsh)
indent_script_test(bad_geo_parameter_value ${EXPECT_ERROR} "-mesh_geo_parameters: 'abc' for 'h_tip' is not a number"
  ${INDENT} ${PAPER_COARSE} -mesh_geo_parameters h_tip=abc -output_dir ${BAD_DIR}/parameter_value)

# ---- options files, checked before PETSc reads them (issue 25): one line, not PETSc's error block
indent_script_test(bad_options_file_missing ${EXPECT_ERROR}
  "-options_file '${BAD_DIR}/no_such.opts': No such file or directory"
  ${INDENT} -options_file ${BAD_DIR}/no_such.opts)
bad_np2(bad_options_file_directory_np2 ${EXPECT_ERROR}
  "-options_file '${CMAKE_CURRENT_SOURCE_DIR}': it is a directory"
  ${INDENT_NP2} -options_file ${CMAKE_CURRENT_SOURCE_DIR})
# A file saved with a UTF-8 byte-order mark is read as the same file without it.
add_test(NAME options_file_bom COMMAND sh -c "mkdir -p \"$(dirname \"$0\")\" && printf '\\357\\273\\277-dm_plex_box_faces 2,2,2\\n-quiet\\n' > \"$0\" && \"$@\""
  ${BAD_DIR}/bom.opts ${INDENT} -options_file ${BAD_DIR}/bom.opts ${ELASTIC} -bc_fixed bottom
  -bc_displacement top:z=-0.01 -output_fields 0 -output_dir ${BAD_DIR}/bom -output_overwrite)
set_tests_properties(options_file_bom PROPERTIES ENVIRONMENT "${INDENT_TEST_ENV}" LABELS "input;faults"
  FAIL_REGULAR_EXPRESSION "error|ERROR")

# ---- physically meaningless runs, refused before solving
indent_script_test(bad_never_touches_surface ${EXPECT_ERROR}
  "${RE_NEVER_TOUCHES}"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -indenter_surface 2)
bad_np2(bad_never_touches_axis_np2 ${EXPECT_ERROR}
  "The indenter never touches the contact surface 'top'.*-indenter_axis 5,5 nm"
  ${INDENT_NP2} ${OK_BOX} ${ELASTIC} ${SPHERE} -indenter_axis 5,5)
# The indenter starting inside the body (issue 25): refused on 1 and 2 ranks.
indent_script_test(bad_indenter_starts_inside ${EXPECT_ERROR} --fresh ${BAD_DIR}/inside
  "The indenter starts inside the body: at depth 0 it reaches 0.5 nm below the contact surface 'top' \\(-indenter_surface 0.5 nm"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -indenter_surface 0.5 -output_dir ${BAD_DIR}/inside)
bad_np2(bad_indenter_starts_inside_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/inside_paper
  "The indenter starts inside the body: at depth 0 it reaches 10 nm below the contact surface 'top'"
  ${INDENT_NP2} ${PAPER_COARSE} -indenter_surface -10 -output_dir ${BAD_DIR}/inside_paper)
# A load program longer than indent.h5 can hold is refused before step 1; a field output beyond
# -output_size_warning (or the free disk) is announced with its estimate, and the run goes on.
bad_np2(bad_steps_beyond_field_file_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/steps_beyond
  "The load program has more than 100000 steps to write and indent.h5 holds at most 100000"
  ${INDENT_NP2} ${PAPER_COARSE} -load_steps 100000 -output_fields 1 -output_fields_every 1
  -output_dir ${BAD_DIR}/steps_beyond)
add_test(NAME output_size_warning COMMAND ${INDENT} -dm_plex_box_faces 2,2,2 -quiet ${ELASTIC} ${SPHERE} -load_steps 20
  -output_size_warning 1e-6 -output_dir ${BAD_DIR}/size_warning -output_overwrite)
set_tests_properties(output_size_warning PROPERTIES ENVIRONMENT "${INDENT_TEST_ENV}" LABELS "input;faults"
  PASS_REGULAR_EXPRESSION "indent: warning: the field output would take about [0-9.e+-]+ GB \\(up to [0-9]+ steps")
# Linear elements lock as nu nears 1/2 (locking.c): a region at or above their Poisson's ratio is announced,
# named, with the element; second-order hexahedra and a ratio below the element's are not.
set(LOCKING_RE "indent: warning: region 'film' \\(nu 0.45\\) on P1 tetrahedra, which lock as a material nears")
add_test(NAME locking_warning_tets_np2 COMMAND ${INDENT_NP2} ${PAPER_COARSE} -film_poisson 0.45 -load_depth 20
  -output_dir ${BAD_DIR}/locking_tets -output_overwrite)
set_tests_properties(locking_warning_tets_np2 PROPERTIES ENVIRONMENT "${INDENT_TEST_ENV}" LABELS "input;faults"
  PROCESSORS 2 PASS_REGULAR_EXPRESSION "${LOCKING_RE}")
add_test(NAME locking_warning_hex COMMAND ${INDENT} -dm_plex_box_faces 2,2,2 -quiet -domain_young 100 -domain_poisson
  0.45 -formulation small ${SPHERE} -output_fields 0 -output_dir ${BAD_DIR}/locking_hex -output_overwrite)
set_tests_properties(locking_warning_hex PROPERTIES ENVIRONMENT "${INDENT_TEST_ENV}" LABELS "input;faults"
  PASS_REGULAR_EXPRESSION "indent: warning: region 'domain' \\(nu 0.45\\) on Q1 hexahedra, which lock")
add_test(NAME locking_none_q2 COMMAND ${INDENT} -dm_plex_box_faces 2,2,2 -quiet -domain_young 100 -domain_poisson 0.49
  -formulation small ${SPHERE} -disc_degree 2 -output_fields 0 -output_dir ${BAD_DIR}/locking_q2 -output_overwrite)
add_test(NAME locking_none_tets_np2 COMMAND ${INDENT_NP2} ${PAPER_COARSE} -film_poisson 0.39 -substrate_poisson 0.39
  -load_depth 20 -output_dir ${BAD_DIR}/locking_none_tets -output_overwrite)
set_tests_properties(locking_none_q2 locking_none_tets_np2 PROPERTIES ENVIRONMENT "${INDENT_TEST_ENV}"
  LABELS "input;faults" FAIL_REGULAR_EXPRESSION "lock as a material")
set_tests_properties(locking_none_tets_np2 PROPERTIES PROCESSORS 2)
# Steps that fail by their linear solves (a Krylov budget of 2 iterations) end with the remedy that helps, a direct
# solve, not with smaller steps.
bad_np2(bad_linear_solves_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/linear_solves
  "${RE_LINEAR_SOLVES}"
  ${INDENT_NP2} -options_file ${CMAKE_SOURCE_DIR}/inputs/berkovich.opts -mesh_file ${PAPER_GEO}
  -mesh_geo_parameters h_tip=15,h_far=300 -load_steps 6 -output_fields 0 -quiet
  -load_max_cutbacks 1 -ksp_max_it 2 -output_dir ${BAD_DIR}/linear_solves)
# A symmetry plane that misses the indenter's axis mirrors the indenter: a pair of indents is announced, an
# overlapping pair refused.
bad_np2(bad_mirror_overlap_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/mirror_overlap
  "-bc_symmetry 'symmetry' \\(the plane y = 0 nm\\) cuts the indenter, whose axis is 100 nm from it"
  ${INDENT_NP2} ${PAPER_COARSE} -indenter_axis 0,100 -output_dir ${BAD_DIR}/mirror_overlap)
add_test(NAME mirror_pair_warning_np2 COMMAND ${INDENT_NP2} ${PAPER_COARSE} -indenter_axis 0,400 -load_depth 20
  -output_dir ${BAD_DIR}/mirror_pair -output_overwrite)
set_tests_properties(mirror_pair_warning_np2 PROPERTIES ENVIRONMENT "${INDENT_TEST_ENV}" LABELS "input;faults"
  PROCESSORS 2 PASS_REGULAR_EXPRESSION
  "indent: warning: -bc_symmetry 'symmetry' \\(the plane y = 0 nm\\) misses the indenter's axis \\(0, 400 nm\\)")
indent_script_test(bad_depth_through_box ${EXPECT_ERROR}
  "-load_depth 2 nm goes through the body: .*the body is 1 nm thick"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -load_depth 2)
bad_np2(bad_depth_through_block_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/through_block
  "${RE_THROUGH_BLOCK}"
  ${INDENT_NP2} ${PAPER_COARSE} -load_depth 2000 -output_dir ${BAD_DIR}/through_block)
bad_np2(bad_rotation_half_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/rotation
  "${RE_ROTATION_HALF}"
  ${INDENT_NP2} ${PAPER_COARSE} -indenter_rotation 30 -output_dir ${BAD_DIR}/rotation)
# A scratch (-scratch_*) that is meaningless or leaves the model.
indent_script_test(bad_scratch_length ${EXPECT_ERROR} "-scratch_length must be >= 0 \\(nm\\), got -5"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -scratch_length -5)
indent_script_test(bad_scratch_direction ${EXPECT_ERROR} "-scratch_direction 0,0 has no direction"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -scratch_length 0.5 -scratch_direction 0,0)
indent_script_test(bad_scratch_steps ${EXPECT_ERROR} "-scratch_steps must be >= 1, got 0"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -scratch_length 0.5 -scratch_steps 0)
indent_script_test(bad_scratch_steps_alone ${EXPECT_ERROR} "-scratch_steps needs a scratch: -scratch_length > 0"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -scratch_steps 4)
indent_script_test(bad_scratch_no_indenter ${EXPECT_ERROR} "-scratch_length needs an indenter: -indenter_type"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -scratch_length 0.5)
indent_script_test(bad_scratch_off_surface ${EXPECT_ERROR}
  "-scratch_length 5 nm takes the indenter's axis from \\(0, 0\\) to \\(5, 0\\) nm, off the contact surface 'top' \\(x from 0 to 1"
  ${INDENT} ${OK_BOX} ${ELASTIC} ${SPHERE} -scratch_length 5)
bad_np2(bad_scratch_leaves_mirror_np2 ${EXPECT_ERROR} --fresh ${BAD_DIR}/scratch_mirror
  "-scratch_direction 0,1 leaves the symmetry plane 'symmetry' \\(y = 0 nm\\) through the indenter's axis"
  ${INDENT_NP2} ${PAPER_COARSE} -scratch_length 50 -scratch_direction 0,1 -output_dir ${BAD_DIR}/scratch_mirror)
indent_script_test(bad_rotation_quarter ${EXPECT_ERROR}
  "${RE_ROTATION_QUARTER}"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -bc_symmetry left,front -indenter_type berkovich -load_depth 0.1)
indent_script_test(bad_rotation_vickers ${EXPECT_ERROR}
  "-indenter_rotation 30 degrees: the vickers indenter .* use a rotation of 0, 45, 90, ... degrees"
  ${INDENT} ${OK_BOX} ${ELASTIC} -bc_fixed bottom -bc_symmetry front -indenter_type vickers -load_depth 0.1
  -indenter_rotation 30)
# A load step that fails too often is the user's to fix too: one line, no traceback.
indent_script_test(bad_steps_fail ${EXPECT_ERROR}
  "Load step from load factor 0\\.? failed 1 times in a row .*raise -load_max_cutbacks"
  ${INDENT} ${OK_BOX} ${PLASTIC} -bc_fixed bottom -bc_displacement top:z=-0.2 -snes_max_it 1 -load_max_cutbacks 0)

# ---- -help lists, it does not run, mesh or write
indent_script_test(help_lists_options_np2 ${CMAKE_CURRENT_SOURCE_DIR}/check_help.sh ${CMAKE_CURRENT_BINARY_DIR}/help
  ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} 2 $<TARGET_FILE:indent> -options_file
  ${CMAKE_SOURCE_DIR}/inputs/berkovich.opts
  -mesh_file ${PAPER_GEO} -mesh_geo_parameters h_tip=60,h_far=600,r_fine=200)
set_tests_properties(help_lists_options_np2 PROPERTIES PROCESSORS 2)
# A bad value under -help: the listing of what was read, then the one error line.
indent_script_test(help_bad_value ${EXPECT_ERROR} --absent ${BAD_DIR}/help_bad_value --after-output
  "-load_depth: '60nm' is not a number \\(nm\\)"
  ${INDENT} -options_file ${CMAKE_SOURCE_DIR}/inputs/berkovich.opts -mesh_file ${PAPER_GEO} -load_depth 60nm
  -output_dir ${BAD_DIR}/help_bad_value -help)

# ---- checks made while the load program runs (src/solvers/run_checks.c)
add_executable(test_run_checks test_run_checks.c)
target_link_libraries(test_run_checks PRIVATE indentcore)
set(RC_BOX -dm_plex_box_faces 4,4,2 -output_fields 0 -quiet ${ELASTIC})
set(RC_SPHERE "-bc_fixed bottom -indenter_type sphere -indenter_axis 0.5,0.5 -load_steps 2")
string(CONCAT RC_QUARTER "-bc_fixed bottom -bc_symmetry left,front -indenter_type sphere -indenter_radius 1 "
  "-load_depth 0.05 -load_steps 2")
string(CONCAT RC_AWAY "-bc_displacement bottom:xyz=-0.5 -indenter_type sphere -indenter_axis 0.5,0.5 -load_steps 2 "
  "-indenter_radius 1 -load_depth 0.1")
foreach(rc
    # a sphere of radius 1e6 nm: the contact covers the whole top and reaches its edge
    "edge_np1|1|-check edge -expect 1 ${RC_SPHERE} -indenter_radius 1e6 -load_depth 0.05"
    "edge_np2|2|-check edge -expect 1 ${RC_SPHERE} -indenter_radius 1e6 -load_depth 0.05"
    # a small sphere in the middle does not
    "edge_small_np2|2|-check edge -expect 0 ${RC_SPHERE} -indenter_radius 1 -load_depth 0.05"
    # on a quarter model the contact reaches the symmetry planes, which are not edges
    "edge_quarter_np2|2|-check edge -expect 0 ${RC_QUARTER}"
    "area_np2|2|-check area -expect 1 ${RC_SPHERE} -indenter_radius 1 -load_depth 0.05"
    # small strain lets a block compressed by 150% invert; by 10% it does not
    "inverted_np2|2|-check inverted -expect 1 -bc_fixed bottom -bc_displacement top:z=-1.5"
    "inverted_mild_np2|2|-check inverted -expect 0 -bc_fixed bottom -bc_displacement top:z=-0.1"
    # the block moved down 0.5 nm by its bottom, away from an indenter going 0.1 nm deep: no contact by the
    # end of loading (a prescribed displacement: not decided before solving)
    "loading_np2|2|-check loading -expect 1 ${RC_AWAY}"
    "loading_touches_np2|2|-check loading -expect 0 ${RC_SPHERE} -indenter_radius 1 -load_depth 0.1")
  string(REPLACE "|" ";" parts "${rc}")
  list(GET parts 0 rcname)
  list(GET parts 1 rcnp)
  list(GET parts 2 rcopts)
  separate_arguments(rcopts)
  indent_mpi_test(NAME run_checks_${rcname} NP ${rcnp} LABELS unit
    COMMAND $<TARGET_FILE:test_run_checks> ${RC_BOX} ${rcopts} -output_dir
    ${CMAKE_CURRENT_BINARY_DIR}/run_checks_${rcname})
endforeach()
