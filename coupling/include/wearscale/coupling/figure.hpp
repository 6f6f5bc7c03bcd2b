#pragma once
// A figure: a gnuplot script of a fixed kind and the texts it draws (titles,
// legend entries, the names of its data files, numbers), drawn as a PNG and a
// PDF beside the data, when gnuplot is installed (Debian: gnuplot-nox).
//
// No character of a text reaches gnuplot's parser, by construction: a kind's
// script is constant text, the same for every run; the texts are written
// apart, to <name>_labels.tsv, each as its UTF-8 bytes in hexadecimal, and the
// script decodes them into string values (never into commands: no macro,
// eval, load or system on them). gnuplot is started from an argument vector
// (no shell) in the figure's folder (its scratch copy), with relative names.
//
// The script and its texts stay beside the figure: `gnuplot <name>.gp` in the
// folder draws <name>.png and <name>.pdf again, to edit them, or where
// wearscale ran without gnuplot (the scripts are written all the same).
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace wearscale::coupling {

struct Figure {
  /// The files' stem: <name>.png, <name>.pdf, <name>.gp, <name>_labels.tsv
  /// (a plain file name, not starting with '-' or '.').
  std::string name;
  /// What its kind draws: gnuplot commands run after the common prologue
  /// that defines `name`, given_text(k) and given_number(k). Made of wearscale's own
  /// text only (never of a case's, a path's or a name's: those are texts).
  std::string script;
  /// What each text is (a word for the reader of the .tsv) and the text:
  /// given_text(1), given_text(2), ... in this order; given_number(k) reads one as a number.
  std::vector<std::pair<std::string, std::string>> texts;
  /// The files it reads, relative to its folder (also named in `texts`).
  std::vector<std::filesystem::path> data;

  /// Adds a text; returns its index k for given_text(k).
  std::size_t add(std::string what, std::string text);
  /// Adds a number (17 significant digits; "nan", "inf"): given_number(k) reads it.
  std::size_t add(std::string what, double value);
};

/// Whether `gnuplot` is on the PATH (looked up once).
bool plotting_available();

/// Draws `figures` in `folder` with two gnuplot processes side by side, each
/// drawing every other figure in turn (one process for one figure; one more
/// per figure only if one of them fails): writes each figure's script and texts, and its
/// PNG and PDF, every file atomically and staged with the folder's output set
/// when one is open. A figure gnuplot could not draw is a warning, not an
/// error; a figure left incomplete (a full disk) is an OutputError; a signal
/// stopping gnuplot is Interrupted. Returns the files written.
std::vector<std::filesystem::path> draw_figures(const std::filesystem::path& folder,
                                                const std::vector<Figure>& figures);

/// The most bytes of a text in a figure: gnuplot reads at most 1023
/// characters of a field of a data file, and a byte takes two hexadecimal
/// digits. A longer text is cut before a character and ends with "…".
inline constexpr std::size_t kMaxTextBytes = 500;

/// The texts file of a figure as draw_figures writes it: one line per text,
/// "<what>\tx<hex of its UTF-8 bytes>" (the 'x' keeps an empty text a field),
/// each text at most kMaxTextBytes bytes.
std::string figure_texts_file(const Figure& figure);

/// The whole script of a figure (the prologue, then its kind's commands).
std::string figure_script(const Figure& figure);

/// `text` fit for a figure: control characters as spaces (line breaks kept
/// if `lines`), bytes that are not UTF-8 as U+FFFD, at most `max_chars`
/// characters (an ellipsis ends a longer one).
std::string figure_text(std::string_view text, std::size_t max_chars = 120, bool lines = false);

}  // namespace wearscale::coupling
