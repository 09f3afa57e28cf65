// `stride export`: reads a system in any format and hands it to the SSP or OSP writer.
#include "export.hpp"

#include <cstdio>

#include "installed_files.hpp"
#include "stride/cosim/error.hpp"
#include "stride/cosim/system_export.hpp"
#include "stride/cosim/system_import.hpp"

namespace stride::cli {

CLI::App* add_export_command(CLI::App& app, export_arguments& a) {
  CLI::App* c = app.add_subcommand(
      "export",
      "Write a system (XML, SSP or OSP) as an SSP 1.0 archive or an OSP system structure, with "
      "its FMUs; what the format cannot say is refused, naming it (docs/ssp.md, Export)");
  c->add_option("system", a.system, "System XML file, SSP or OSP system")
      ->required()
      ->transform(existing_or_installed_model());
  auto* ssp = c->add_option("--ssp", a.ssp,
                            "Write this SSP archive (NAME.ssp): SystemStructure.ssd, the FMUs "
                            "and parameters.ssv under resources/");
  auto* osp =
      c->add_option("--osp", a.osp, "Write OspSystemStructure.xml and the FMUs into this folder");
  ssp->excludes(osp);
  osp->excludes(ssp);
  c->add_flag("--force", a.force,
              "Replace an existing archive, or write into a non-empty folder (files of the same "
              "name are replaced)");
  c->add_flag("--quiet,-q", a.quiet, "Print nothing but errors");
  c->footer(
      "Examples:\n  stride export models/walk.xml --ssp walk.ssp\n"
      "  stride export pair.ssp --osp pair-osp --force");
  return c;
}

int export_system(const export_arguments& a) {
  if (a.ssp.empty() == a.osp.empty()) {
    throw cosim::validation_error("export: give --ssp OUT.ssp or --osp DIR");
  }
  const cosim::system_structure system = cosim::load_system_file(a.system);
  cosim::export_options options;
  options.overwrite = a.force;
  const cosim::export_report report = a.ssp.empty() ? cosim::export_osp(system, a.osp, options)
                                                    : cosim::export_ssp(system, a.ssp, options);
  if (!a.quiet) {
    std::printf("wrote %s:\n", report.target.string().c_str());
    for (const auto& f : report.files) std::printf("  %s\n", f.c_str());
  }
  return 0;
}

}  // namespace stride::cli
