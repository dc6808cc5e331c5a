// assess: command-line front end of libassess.
#include "commands.hpp"

#include <assess/support/error.hpp>

#include <cstdio>
#include <exception>
#include <iostream>


void assess::cli::print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::cerr << "assess: warning: " << w << "\n";
}

int main(int argc, char** argv) {
  CLI::App app{
      "assess: out-of-plane seismic assessment of masonry walls\n"
      "(NTC 2018 / Circolare 2019 spectra, kinematic checks, rocking dynamics)"};
  app.set_version_flag("--version", ASSESS_VERSION_STRING);
  app.require_subcommand(1);
  assess::cli::add_spectrum_command(app);
  assess::cli::add_kinematic_command(app);
  assess::cli::add_rocking_command(app);
  assess::cli::add_run_command(app);
  assess::cli::add_campaign_command(app);
  assess::cli::add_fragility_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : assess::cli::exit_input_error;
  } catch (const assess::InputError& e) {
    std::cerr << "assess: error: " << e.what() << "\n";
    return assess::cli::exit_input_error;
  } catch (const std::exception& e) {
    std::cerr << "assess: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
