// `asperity contact`: forward and inverse contact of a physical surface, CSV out.
#pragma once

namespace asperity::cli {

// argv[0] is "contact"; returns the exit status (0 ok, 2 bad usage or input).
int contact_command(int argc, char** argv);
extern const char* contact_usage;

}  // namespace asperity::cli
