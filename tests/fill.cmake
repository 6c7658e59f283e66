# test_fill_spiral floods a 20,000 x 20,000 image (1.6 GB): in sanitizer builds,
# where that would take minutes, it checks only the small spirals; it reports
# itself skipped (exit code 77) when the big image cannot be allocated.
set_tests_properties(test_fill_spiral PROPERTIES SKIP_RETURN_CODE 77)
if(CG_SANITIZE)
  target_compile_definitions(test_fill_spiral PRIVATE CG_TEST_SANITIZED)
endif()
