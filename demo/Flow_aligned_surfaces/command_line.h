// The command line of the demo's programs, in one place.
// - Options parsed by Boost.Program_options, with numbers read strictly: the whole text or
//   nothing ("--faces 12x", "--size 0.1abc", "--center 1,2,3x" are refused with the option and
//   the text named).
// - `--help` (the usage, what the program does, every option with its default and unit) and
//   `--version`, which write nothing and exit with 0.
// - The options every program has: --output DIR, --overwrite, --quiet.
// - The output folder: a non-empty one is refused unless --overwrite; the run writes into a
//   staging folder beside it and moves its files into place only when it succeeds, so that a
//   failed run leaves the folder as it was, and a successful one leaves no file of an earlier run.
// - The progress lines of long runs (iteration, flux, elapsed time), silenced by --quiet.

#ifndef FAS_DEMO_COMMAND_LINE_H
#define FAS_DEMO_COMMAND_LINE_H

#include <CGAL/Flow_aligned_surfaces/Alignment.h>

#include <boost/any.hpp>
#include <boost/program_options.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <iostream>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#ifndef FAS_DEMO_PACKAGE_VERSION // set by the demo's CMakeLists.txt from the project's version
#define FAS_DEMO_PACKAGE_VERSION "unknown"
#endif

namespace fas_demo {

namespace po = boost::program_options;

/// The version of the package the program was built from (CMake's `project(... VERSION ...)`).
inline const char* package_version()
{
  return FAS_DEMO_PACKAGE_VERSION;
}

// ---- Option values, read strictly --------------------------------------------------------

/// Refuses the text of the option being parsed; Boost.Program_options fills in the option's name.
[[noreturn]] inline void refuse_option_value(const std::string& text, const std::string& expected)
{
  throw po::error_with_option_name("%canonical_option%: expected " + expected + ", got '" + text + "'");
}

/// The number `text` is, all of it, when it is finite (no sign, spaces, suffix or "inf").
inline std::optional<double> parse_number(const std::string& text)
{
  double x = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, x);
  if (text.empty() || error != std::errc() || stop != end || !std::isfinite(x))
    return std::nullopt;
  return x;
}

/// A whole number from `Min` to `Max`, written with digits only ("12x", "-3", "1e3" are refused).
template <std::size_t Min, std::size_t Max>
struct Whole_number {
  std::size_t value = Min;
};

/// The number of triangles of a patch (the library's patches need two; ten million is the most
/// the programs accept).
using Face_count = Whole_number<2, 10'000'000>;

template <std::size_t Min, std::size_t Max>
std::ostream& operator<<(std::ostream& os, const Whole_number<Min, Max>& n)
{
  return os << n.value;
}

template <std::size_t Min, std::size_t Max>
void validate(boost::any& v, const std::vector<std::string>& values, Whole_number<Min, Max>*, int)
{
  po::validators::check_first_occurrence(v);
  const std::string& text = po::validators::get_single_string(values);
  std::size_t n = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, n);
  if (text.empty() || error != std::errc() || stop != end || n < Min || n > Max)
    refuse_option_value(text, "a whole number from " + std::to_string(Min) + " to " + std::to_string(Max));
  v = Whole_number<Min, Max>{n};
}

/// A finite number greater than 0 (a size, a spacing, a length, a time).
struct Positive_number {
  double value = 1;
};

inline std::ostream& operator<<(std::ostream& os, const Positive_number& x)
{
  return os << x.value;
}

inline void validate(boost::any& v, const std::vector<std::string>& values, Positive_number*, int)
{
  po::validators::check_first_occurrence(v);
  const std::string& text = po::validators::get_single_string(values);
  const std::optional<double> x = parse_number(text);
  if (!x || !(*x > 0))
    refuse_option_value(text, "a number greater than 0");
  v = Positive_number{*x};
}

/// Three finite numbers written X,Y,Z (a point or a direction).
struct Triple {
  std::array<double, 3> value{};
};

inline std::ostream& operator<<(std::ostream& os, const Triple& t)
{
  return os << t.value[0] << ',' << t.value[1] << ',' << t.value[2];
}

inline void validate(boost::any& v, const std::vector<std::string>& values, Triple*, int)
{
  po::validators::check_first_occurrence(v);
  const std::string& text = po::validators::get_single_string(values);
  Triple t;
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t comma = i < 2 ? text.find(',', start) : text.size();
    const std::optional<double> x =
        comma == std::string::npos ? std::nullopt : parse_number(text.substr(start, comma - start));
    if (!x)
      refuse_option_value(text, "three numbers X,Y,Z");
    t.value[i] = *x;
    start = comma + 1;
  }
  v = t;
}

// ---- Parsing and help ----------------------------------------------------------------------

/// A group of options as `--help` prints it: 100 columns, descriptions from column 50 at most.
inline po::options_description option_group(const std::string& caption)
{
  return po::options_description(caption, 100, 50);
}

/// What `--help` says about a program besides its options.
struct Program_help {
  std::string synopsis;    ///< e.g. "align_patch [options]"
  std::string description; ///< what it does and writes, a paragraph or more
};

/// Parses `argv` into the variables bound to `options` (and `positional` arguments, if any).
/// Adds --help and --version.  Returns the exit status when the program must stop here: 0 after
/// --help (usage, description and options on standard output) or --version, 2 after a bad
/// command line (the message names the option and the text, on standard error); nothing when
/// the program goes on.  With --quiet (`add_output_options()`), standard output is silenced
/// from here on.
inline std::optional<int> parse_command_line(int argc, char** argv, const Program_help& help,
                                             po::options_description options,
                                             const po::positional_options_description& positional = {})
{
  options.add_options()("help", "print this help and exit")("version",
                                                            "print the package's version and exit");
  // Long options only, spelled out: a value such as "-1,0,0" is a value, not an option.
  const int style = po::command_line_style::unix_style & ~po::command_line_style::allow_short &
                    ~po::command_line_style::allow_guessing;
  po::variables_map vm;
  try {
    const po::parsed_options parsed =
        po::command_line_parser(argc, argv).options(options).positional(positional).style(style).run();
    // "--output --flow" is a forgotten value, not a folder named "--flow" ("--output=--flow" is one).
    for (const po::option& o : parsed.options)
      if (o.original_tokens.size() > 1 && !o.value.empty() && o.value.front().rfind("--", 0) == 0)
        throw po::error("--" + o.string_key + ": expected a value, got the option '" + o.value.front() + "'");
    po::store(parsed, vm);
    if (vm.count("help")) {
      std::cout << "Usage: " << help.synopsis << "\n\n"
                << help.description << "\n\n"
                << options << std::flush;
      return 0;
    }
    if (vm.count("version")) {
      std::cout << "Flow_aligned_surfaces " << package_version() << "\n";
      return 0;
    }
    po::notify(vm);
  } catch (const po::error& e) {
    std::cerr << "error: " << e.what() << " ("
              << (argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "the program")
              << " --help lists the options)\n";
    return 2;
  }
  if (vm.count("quiet") && vm["quiet"].as<bool>())
    std::cout.setstate(std::ios_base::badbit); // what the program prints goes nowhere
  return std::nullopt;
}

// ---- The output folder ---------------------------------------------------------------------

/// The options of every program that writes a folder.
struct Output_options {
  std::string folder;
  bool overwrite = false;
  bool quiet = false;
};

/// --output DIR (default `default_folder`), --overwrite and --quiet.
inline po::options_description output_options(Output_options& output, const std::string& default_folder)
{
  po::options_description options = option_group("Output");
  options.add_options()("output", po::value(&output.folder)->default_value(default_folder)->value_name("DIR"),
                        "the folder to write into; created when missing; refused when it is not empty, "
                        "unless --overwrite")(
      "overwrite", po::bool_switch(&output.overwrite),
      "write into a non-empty --output folder: the files in it (an earlier run's) are replaced by this "
      "run's, and removed when this run does not write them; refused for a folder with sub-folders, "
      "the current folder and one that holds an input")(
      "quiet", po::bool_switch(&output.quiet),
      "print nothing but warnings and errors (no progress, no results)");
  return options;
}

/// The folder a run writes into.  open() checks it and creates a staging folder beside it,
/// path(); the run writes there; commit() puts the files in place (the earlier files of the
/// folder, with --overwrite, go at that moment).  Without commit() -- the run failed -- the
/// staging folder is removed and the folder is left as it was.
class Output_folder {
public:
  Output_folder() = default;
  Output_folder(const Output_folder&) = delete;
  Output_folder& operator=(const Output_folder&) = delete;
  ~Output_folder()
  {
    std::error_code ec;
    if (!m_staging.empty())
      std::filesystem::remove_all(m_staging, ec);
  }

  /// Checks `options.folder` and creates the staging folder; prints why and returns false when
  /// the folder is refused or cannot be written.  With --overwrite, a folder that holds the
  /// current directory or one of the run's `inputs` (files) is refused: its files would go.
  bool open(const Output_options& options, const std::vector<std::string>& inputs = {})
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    m_destination = fs::absolute(options.folder, ec).lexically_normal();
    if (m_destination.has_filename() == false) // "out/" names the folder "out"
      m_destination = m_destination.parent_path();
    const auto fail = [&](const std::string& why) {
      std::cerr << "error: --output: " << options.folder << ": " << why << "\n";
      return false;
    };
    if (ec || !m_destination.has_filename() || m_destination == m_destination.root_path())
      return fail("not a folder a program can write into");
    const fs::file_status status = fs::status(m_destination, ec);
    if (fs::exists(status)) {
      if (!fs::is_directory(status))
        return fail("exists and is not a folder");
      bool empty = true;
      for (const fs::directory_entry& entry : fs::directory_iterator(m_destination, ec)) {
        if (!options.overwrite)
          return fail("the folder is not empty (an earlier run?); give --overwrite to replace its files, "
                      "or choose another folder");
        if (entry.is_directory()) // an earlier run's folder of files (the main job's iterations)
          for (const fs::directory_entry& inner : fs::directory_iterator(entry.path(), ec))
            if (inner.is_directory())
              return fail("the folder holds the folder " + inner.path().string() +
                          "; --overwrite replaces only a folder of files and of folders of files (an "
                          "earlier run's output)");
        empty = false;
      }
      if (ec)
        return fail("cannot read the folder: " + ec.message());
      // Its files will go: not those of the folder the user is in, nor the run's inputs.
      const auto inside = [this](const fs::path& path) {
        std::error_code ignored;
        const fs::path file = fs::weakly_canonical(path, ignored);
        const fs::path folder = fs::weakly_canonical(m_destination, ignored);
        return std::mismatch(folder.begin(), folder.end(), file.begin(), file.end()).first == folder.end();
      };
      if (!empty && inside(fs::current_path(ec)))
        return fail("--overwrite would remove the files of the folder you are in; give a folder of its own");
      for (const std::string& input : inputs)
        if (!empty && !input.empty() && inside(input))
          return fail("--overwrite would remove the input " + input + "; give a folder of its own");
    }
    fs::create_directories(m_destination.parent_path(), ec);
    m_staging = m_destination.parent_path() /
                ("." + m_destination.filename().string() + ".partial-" + std::to_string(::getpid()));
    fs::remove_all(m_staging, ec); // left by a crashed run that had the same process id
    if (!fs::create_directory(m_staging, ec)) {
      m_staging.clear();
      return fail("cannot create a folder beside it" + (ec ? ": " + ec.message() : std::string()));
    }
    return true;
  }

  /// Where the run writes its files until commit().
  const std::filesystem::path& path() const { return m_staging; }
  /// Where the files are after commit() (absolute).
  const std::filesystem::path& destination() const { return m_destination; }

  /// The files written so far, relative to path() (with '/'), sorted.
  std::vector<std::string> files() const
  {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(m_staging, ec))
      if (entry.is_regular_file())
        names.push_back(entry.path().lexically_relative(m_staging).generic_string());
    std::sort(names.begin(), names.end());
    return names;
  }

  /// Moves the run's files into the folder, after removing the files an earlier run left there;
  /// prints why and returns false when it cannot.
  bool commit()
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(m_destination, ec)) {
      fs::rename(m_staging, m_destination, ec); // all at once
    }
    else {
      for (const fs::directory_entry& entry : fs::directory_iterator(m_destination, ec))
        if (!entry.is_directory())
          fs::remove(entry.path(), ec);
        else // a folder of files (checked by open())
          fs::remove_all(entry.path(), ec);
      for (const fs::directory_entry& entry : fs::directory_iterator(m_staging, ec))
        if (!ec)
          fs::rename(entry.path(), m_destination / entry.path().filename(), ec);
      if (!ec)
        fs::remove(m_staging, ec);
    }
    if (ec) {
      std::cerr << "error: --output: cannot move the results into " << m_destination.string() << ": "
                << ec.message() << "\n";
      return false;
    }
    m_staging.clear();
    return true;
  }

private:
  std::filesystem::path m_destination, m_staging;
};

// ---- Progress ------------------------------------------------------------------------------

/// The progress lines of a deformation: "NAME: iteration I, flux F, T s elapsed" for the first
/// iteration and then at most one a second (a visitor of `Flow_aligned_deformation`).  --quiet
/// silences them with the rest of standard output.
class Progress {
public:
  /// `fractions`: the library's `callback` (a deformation's `run()`) gives the share of the
  /// iterations done, and the lines are printed then; otherwise (single `step()`s) by the visitor.
  explicit Progress(std::string name, bool fractions = true)
      : m_name(std::move(name)), m_fractions(fractions), m_start(std::chrono::steady_clock::now()),
        m_last(m_start)
  {
  }

  /// The deformation's `visitor`: the iteration's report.
  void operator()(const CGAL::Flow_aligned_surfaces::Iteration_report& r)
  {
    m_report = r;
    if (!m_fractions)
      print(std::string());
  }

  /// The library's `callback`, called after the visitor.  Never asks to stop.
  bool operator()(double fraction_done)
  {
    print(" (" + std::to_string(std::lround(100 * fraction_done)) + " % of the most)");
    return true;
  }

private:
  // A line at most once a second.
  void print(const std::string& share)
  {
    const auto now = std::chrono::steady_clock::now();
    if (m_printed && now - m_last < std::chrono::seconds(1))
      return;
    m_printed = true;
    m_last = now;
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    std::cout << m_name << ": iteration " << m_report.iteration << share << ", flux "
              << m_report.normalized_flux << ", " << std::round(10 * elapsed) / 10 << " s elapsed"
              << std::endl;
  }

  std::string m_name;
  bool m_fractions;
  std::chrono::steady_clock::time_point m_start, m_last;
  CGAL::Flow_aligned_surfaces::Iteration_report m_report;
  bool m_printed = false;
};

} // namespace fas_demo

#endif // FAS_DEMO_COMMAND_LINE_H
