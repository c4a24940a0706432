# Compiler flags shared by every target of the project (not exported to users).
add_library(simdphys_warnings INTERFACE)
target_compile_options(simdphys_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow)

# Exact results across paths: no target may fuse a multiply and an add behind our back. Kernels
# that want FMA call it explicitly.
add_library(simdphys_exact_fp INTERFACE)
target_compile_options(simdphys_exact_fp INTERFACE -ffp-contract=off)
