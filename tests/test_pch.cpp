// The owner of the test executables' shared precompiled header (tests/CMakeLists.txt): CMake
// builds a precompiled header for a target with sources, and this one needs none of its own.
