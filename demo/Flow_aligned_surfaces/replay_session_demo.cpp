// Replays interactive deformation sessions (Section 4 of the paper) and draws the paper's
// Figure 6: the normalized flux of every iteration, with the "flux spikes" that the user's
// translations, rotations and growing steps cause and the iterations remove.
//
// Usage: replay_session [--flow NAME | --field FILE [--array NAME]] [--output DIR] [--overwrite]
//                       [--quiet] SESSION...
//
// Each SESSION is a text file read by IO::read_session() (one operation a line: iterate N |
// iterate until-converged, translate dx dy dz, rotate ax ay az degrees, grow distance
// [dx dy dz | across-flow], save path).  The flow is the session's own `flow` line (a built-in
// flow's name, or a data file relative to the session file) unless --flow or --field is given.
// Every session file is read and checked before anything runs.  For each session the program
// writes, into DIR (default replay_session_output):
//   - the surface at every `save` (.vtp with the velocity and per-face flux, or .ply/.off/.obj),
//   - STEM.csv: one row per iteration (normalized flux, largest requested rotation, ...),
// and for all of them together flux.png, the plot of the CSV files drawn by gnuplot (when
// gnuplot is not installed, a warning says so and everything else is still written).

#include "command_line.h"
#include "demo_support.h"

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_session.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/replay_session.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

using namespace fas_demo;
namespace fs = std::filesystem;

struct Loaded_session {
  fs::path file;
  FAS::Session session;
};

// The session's files are written by extension; anything else is refused before the replay.
bool is_supported_surface_file(const fs::path& path)
{
  const std::string ext = path.extension().string();
  return ext == ".vtp" || ext == ".ply" || ext == ".off" || ext == ".obj";
}

bool save_surface(const fs::path& path, const Mesh& tm, const Flow& flow)
{
  if (path.extension() == ".vtp")
    return write_surface_VTP(path, tm, flow);
  if (CGAL::IO::write_polygon_mesh(path.string(), tm, CGAL::parameters::stream_precision(17)))
    return true;
  std::cerr << "error: cannot write " << path << "\n";
  return false;
}

std::size_t number_of_words(const std::string& text)
{
  std::size_t words = 0;
  for (std::size_t i = 0; i < text.size(); ++i)
    words += text[i] != ' ' && (i == 0 || text[i - 1] == ' ');
  return words;
}

bool write_csv(const fs::path& path, const FAS::Session_replay_report& replay)
{
  std::ofstream os(path);
  os << std::setprecision(17);
  os << "iteration,session_line,normalized_flux,sampled_area_fraction,max_rotation_angle,max_vertex_step,"
        "converged,number_of_moves_before,moves_before\n";
  for (const FAS::Session_iteration& it : replay.iterations)
    os << it.report.iteration << ',' << it.line << ',' << csv_field(it.report.normalized_flux.value) << ','
       << it.report.normalized_flux.sampled_area_fraction << ',' << it.report.max_rotation_angle << ','
       << it.report.max_vertex_step << ',' << (it.report.converged ? 1 : 0) << ','
       << number_of_words(it.moves_before) << ',' << it.moves_before << '\n';
  if (!os) {
    std::cerr << "error: cannot write " << path << "\n";
    return false;
  }
  return true;
}

// Figure 6: f_n per iteration, one curve per session; an iteration that follows a move is
// marked with a ring (its flux is the spike that the move caused).
bool plot_flux(const fs::path& png, const std::vector<fs::path>& csv_files,
               const std::vector<std::string>& titles)
{
  std::string script =
      "set terminal pngcairo size 960,540 font ',11'\nset output '" + png.string() +
      "'\nset datafile separator comma\nset title 'normalized flux of every iteration; rings: after a user "
      "operation (cf. the paper, Figure 6)' noenhanced\nset xlabel 'iteration'\nset ylabel "
      "'normalized flux f_n'\nset yrange [-0.02:1.02]\nset grid\nset key outside right noenhanced\n"
      "plot ";
  for (std::size_t i = 0; i < csv_files.size(); ++i) {
    const std::string file = "'" + csv_files[i].string() + "'";
    script += (i ? ", " : "") + file + " skip 1 using 1:3 with linespoints pt 7 ps 0.6 lc " +
              std::to_string(i + 1) + " title '" + titles[i] + "', " + file +
              " skip 1 using 1:($7 > 0 ? $3 : NaN) with points pt 6 ps 1.8 lc " + std::to_string(i + 1) +
              " notitle";
  }
  script += "\n";
  FILE* gnuplot = popen("gnuplot 2>&1", "w");
  if (!gnuplot)
    return false;
  std::fwrite(script.data(), 1, script.size(), gnuplot);
  const int status = pclose(gnuplot);
  return status == 0 && fs::exists(png);
}

int main(int argc, char** argv)
{
  std::string flow_name, field_file, array;
  std::vector<std::string> session_files;
  Output_options output;
  po::options_description options = option_group("Options");
  options.add_options()(
      "flow", po::value(&flow_name)->value_name("NAME"),
      (std::string("the flow of every session instead of its own 'flow' line: a built-in flow (") +
       built_in_flow_names() + ") or a data file")
          .c_str())("field", po::value(&field_file)->value_name("FILE"),
                    "the flow of every session, read from a data file (any format of --flow's files)")(
      "array", po::value(&array)->value_name("NAME"),
      "the velocity array of the data file (default: its first vector array)")(
      "session", po::value(&session_files)->value_name("FILE"),
      "a session file; the files may also be given without the option name, as SESSION...");
  options.add(output_options(output, "replay_session_output"));
  po::positional_options_description positional;
  positional.add("session", -1);
  const Program_help help{
      "replay_session [options] SESSION...",
      "Replays interactive deformation sessions (Section 4 of the paper) and draws the paper's Figure 6.\n"
      "Each SESSION is a text file, one operation a line: iterate N | iterate until-converged N,\n"
      "translate dx dy dz, rotate ax ay az degrees, grow distance [dx dy dz | across-flow], save path.\n"
      "Every session is read and checked before anything runs.  Writes into the output folder the surface\n"
      "at every 'save' (.vtp, .ply, .off or .obj), STEM.csv (one row per iteration: normalized flux,\n"
      "largest rotation, ...) per session, and flux.png, the plot of all of them drawn by gnuplot.\n"
      "Progress lines (iteration, flux, elapsed time) go to standard output.  Exit status: 0 on success,\n"
      "1 when a session fails or the output folder is refused (nothing is written then), 2 for a bad\n"
      "command line."};
  if (const std::optional<int> status = parse_command_line(argc, argv, help, options, positional))
    return *status;
  if (session_files.empty()) {
    std::cerr << "error: no session file given (replay_session --help lists the options)\n";
    return 2;
  }
  if (!flow_name.empty() && !field_file.empty()) {
    std::cerr << "error: --flow and --field exclude each other: give one flow\n";
    return 2;
  }
  const std::vector<fs::path> files(session_files.begin(), session_files.end());

  // Read and check everything before doing anything.
  std::vector<Loaded_session> sessions;
  for (const fs::path& file : files) {
    Loaded_session loaded{file, {}};
    std::string error;
    if (!FAS::IO::read_session(file.string(), loaded.session, &error)) {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    for (const auto& op : loaded.session.operations)
      if (op.kind == FAS::Session_operation::Kind::SAVE && !is_supported_surface_file(op.path)) {
        std::cerr << "error: " << file.string() << ": line " << op.line << ": cannot save '" << op.path
                  << "': the file name must end in .vtp, .ply, .off or .obj\n";
        return 1;
      }
    if (flow_name.empty() && field_file.empty() && loaded.session.flow.empty()) {
      std::cerr << "error: " << file.string() << ": the session has no 'flow' line; give --flow or --field\n";
      return 1;
    }
    sessions.push_back(std::move(loaded));
  }
  Output_folder folder;
  std::vector<std::string> inputs = session_files;
  inputs.push_back(field_file);
  if (!folder.open(output, inputs))
    return 1;
  const fs::path& out = folder.path();

  // The flow of a session: the command line's, else the session's built-in name or data file.
  auto flow_of = [&](const Loaded_session& s) -> std::optional<Flow> {
    if (!field_file.empty() || (!flow_name.empty() && !make_built_in_flow(flow_name))) {
      const std::string file = field_file.empty() ? flow_name : field_file;
      if (auto field = read_data_field(file, array))
        return Flow(*field);
      return std::nullopt;
    }
    const std::string name = flow_name.empty() ? s.session.flow : flow_name;
    if (auto flow = make_built_in_flow(name))
      return flow;
    const fs::path data = s.file.parent_path() / name;
    if (!fs::exists(data)) {
      std::cerr << "error: " << s.file.string() << ": flow '" << name << "' is neither a built-in flow ("
                << built_in_flow_names() << ") nor a file\n";
      return std::nullopt;
    }
    if (auto field = read_data_field(data.string(), array))
      return Flow(*field);
    return std::nullopt;
  };

  std::vector<fs::path> csv_files;
  std::vector<std::string> titles;
  for (const Loaded_session& s : sessions) {
    const std::optional<Flow> flow = flow_of(s);
    if (!flow)
      return 1;
    const FAS::Session_patch& p = s.session.patch;
    const Point center(p.center[0], p.center[1], p.center[2]);
    const Vector normal(p.normal[0], p.normal[1], p.normal[2]);
    Mesh tm;
    if (p.shape == FAS::Session_patch::Shape::PLANAR)
      FAS::make_planar_patch(tm, center, normal, p.width, p.height, p.target_number_of_faces);
    else
      FAS::make_disk_patch(tm, center, normal, p.radius, p.target_number_of_faces);

    const std::string stem = s.file.stem().string();
    try {
      Progress progress(stem, false); // replayed iterations are single step()s
      FAS::Flow_aligned_deformation<Mesh, Flow> deformation(tm, *flow, s.session.alignment,
                                                            CGAL::parameters::visitor(std::ref(progress)));
      const FAS::Session_replay_report replay =
          FAS::replay_session(deformation, s.session, [&](const FAS::Session_operation& op) {
            if (!save_surface(out / op.path, tm, *flow))
              throw std::runtime_error("session line " + std::to_string(op.line) + ": cannot save " +
                                       op.path);
          });
      csv_files.push_back(out / (stem + ".csv"));
      titles.push_back(stem);
      if (!write_csv(csv_files.back(), replay))
        return 1;
      std::cout << s.file.string() << ": " << replay.iterations.size() << " iterations, "
                << replay.growths.size() << " growing steps, " << deformation.number_of_factorizations()
                << " factorizations, " << tm.number_of_faces() << " faces at the end, final flux "
                << replay.final_normalized_flux << "\n";
    } catch (const std::exception& e) {
      std::cerr << "error: " << s.file.string() << ": " << e.what() << "\n";
      return 1;
    }
  }

  const fs::path png = out / "flux.png";
  if (!plot_flux(png, csv_files, titles))
    std::cerr << "warning: gnuplot (Debian package gnuplot-nox) did not draw flux.png; the CSV files and "
                 "surfaces are written\n";
  if (!folder.commit())
    return 1;
  std::cout << "results written to " << folder.destination().string() << "\n";
  return 0;
}
