// `asperity eval`: the six integrals at separations read as CSV (eval_csv.hpp has the contract).
#pragma once

namespace CLI {
class App;
}

namespace asperity::cli {

void add_eval_command(CLI::App& app);

}  // namespace asperity::cli
