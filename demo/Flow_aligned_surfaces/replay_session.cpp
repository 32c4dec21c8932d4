// Replays interactive deformation sessions (Section 4 of the paper) and draws the paper's
// Figure 6: the normalized flux of every iteration, with the "flux spikes" that the user's
// translations, rotations and growing steps cause and the iterations remove.
//
// Usage: replay_session [--flow NAME | --field FILE [--array NAME]] [--output DIR] SESSION...
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
  fs::path out = "replay_session_output";
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--flow" && has_value)
      flow_name = argv[++i];
    else if (arg == "--field" && has_value)
      field_file = argv[++i];
    else if (arg == "--array" && has_value)
      array = argv[++i];
    else if (arg == "--output" && has_value)
      out = argv[++i];
    else if (!arg.empty() && arg[0] != '-')
      files.push_back(arg);
    else {
      std::cerr << "usage: " << argv[0] << " [--flow " << built_in_flow_names()
                << " | --field FILE [--array NAME]] [--output DIR] SESSION...\n"
                << "error: unknown or incomplete argument '" << arg << "'\n";
      return 2;
    }
  }
  if (files.empty()) {
    std::cerr << "usage: " << argv[0]
              << " [--flow NAME | --field FILE [--array NAME]] [--output DIR] SESSION...\n"
              << "error: no session file given\n";
    return 2;
  }

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
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) {
    std::cerr << "error: --output: cannot create " << out << ": " << ec.message() << "\n";
    return 1;
  }

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
      FAS::Flow_aligned_deformation<Mesh, Flow> deformation(tm, *flow, s.session.alignment);
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
    std::cerr << "warning: gnuplot (Debian package gnuplot-nox) did not draw " << png.string()
              << "; the CSV files and surfaces are written\n";
  std::cout << "results written to " << fs::absolute(out).string() << "\n";
  return 0;
}
