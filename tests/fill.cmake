# test_fill_spiral floods a 20,000 x 20,000 image (1.6 GB): skipped (exit
# code 77) in sanitizer builds, where it would take minutes.
set_tests_properties(test_fill_spiral PROPERTIES SKIP_RETURN_CODE 77)
if(CG_SANITIZE)
  target_compile_definitions(test_fill_spiral PRIVATE CG_TEST_SANITIZED)
endif()
