// SPDX-License-Identifier: MIT
/// @file
/// prism's version. CMakeLists.txt reads its project version from these three lines, meson.build
/// and CHANGELOG.md are checked against them (tools/check_version.py, a test), and
/// `find_package(prism 0.1 CONFIG)` and `pkg-config --modversion prism` report it.
#pragma once

/// The major version: a change of it may break a program that compiled.
#define PRISM_VERSION_MAJOR 0
/// The minor version: new capabilities (before 1.0, the API may change with it).
#define PRISM_VERSION_MINOR 1
/// The patch version: fixes only.
#define PRISM_VERSION_PATCH 0

/// The version as one number that orders releases: major · 10000 + minor · 100 + patch.
#define PRISM_VERSION (PRISM_VERSION_MAJOR * 10000 + PRISM_VERSION_MINOR * 100 + PRISM_VERSION_PATCH)

#define PRISM_DETAIL_STRINGIFY(x) #x
#define PRISM_DETAIL_VERSION_STRING(a, b, c) PRISM_DETAIL_STRINGIFY(a) "." PRISM_DETAIL_STRINGIFY(b) "." PRISM_DETAIL_STRINGIFY(c)
/// The version as text, "major.minor.patch".
#define PRISM_VERSION_STRING PRISM_DETAIL_VERSION_STRING(PRISM_VERSION_MAJOR, PRISM_VERSION_MINOR, PRISM_VERSION_PATCH)
