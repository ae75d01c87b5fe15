# SFX_SANITIZE: a comma-separated -fsanitize= list (e.g. "address,undefined") applied to every
# target of the build, libraries included, so a report anywhere in our code is caught. Any
# report is fatal (-fno-sanitize-recover=all), so a test that triggers one fails.
set(SFX_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined (empty: none)")
if(SFX_SANITIZE)
  add_compile_options(-fsanitize=${SFX_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${SFX_SANITIZE} -fno-sanitize-recover=all)
  message(STATUS "ScalableFX: sanitizers ${SFX_SANITIZE}")
endif()
