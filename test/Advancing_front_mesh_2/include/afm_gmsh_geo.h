// A reader of the small part of Gmsh's .geo scripting language that the coastline scripts of
// ../shared/data/gmsh (ocean.geo, uk.geo, mediterranean.geo, world.geo) use, so that the tests can mesh their first
// Plane Surface as a PSLG.
//
// What is read: `//` and `/* */` comments; `name = expr;` with + - * / ^, parentheses, numbers, variables, Pi and
// newp, newl (newc), newll (newcl), news, newsl, newv, newreg, newf; Point; Line, Spline, CatmullRom and BSpline;
// Line Loop and Curve Loop; Split Curve; Delete { Point{...}; Line{...}; }; Plane Surface. Lists take ranges `a : b`.
// Statements that cannot change the geometry read here (Physical, Field, Mesh.*, PolarSphere, Coherence, ...) are
// skipped; control flow, includes and transformations are refused, since skipping them could silently give another
// geometry. Reading stops after the first Plane Surface: in the four scripts only size fields, physical groups and
// options follow it.
//
// Every curve stands for the polyline through its listed points. For a BSpline these are control points, which the
// curve does not pass through: the control polygon is then another, nearby coastline, which is fine for a
// robustness test but may cross itself or its neighbours where the real curve does not.
//
// The scripts draw on a PolarSphere, whose stereographic plane is read here as the plane. In world.geo the ocean
// contains the projection pole, so it is unbounded in that plane: no loop encloses the others, and the "outer" loop
// of largest area bounds a continent.
#ifndef AFM_GMSH_GEO_H
#define AFM_GMSH_GEO_H

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_2.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace afm_gmsh_geo {

// Formatted like the other readers' errors, `FILE:LINE: problem` (`FILE: problem` when no line applies, i.e. the
// file cannot be read), with the position kept apart for tests that check it.
class Geo_read_error : public std::runtime_error
{
public:
  Geo_read_error(const std::string& file, std::size_t line, const std::string& problem)
    : std::runtime_error(file + (line != 0 ? ":" + std::to_string(line) : std::string()) + ": " + problem),
      file_(file), line_(line), problem_(problem)
  {}
  const std::string& file() const noexcept { return file_; }
  std::size_t line() const noexcept { return line_; }
  const std::string& problem() const noexcept { return problem_; }

private:
  std::string file_;
  std::size_t line_;
  std::string problem_;
};

namespace internal {

typedef CGAL::Advancing_front_mesh_2::IO::Poly_data Poly_data;

struct Token
{
  enum Kind { END, NUMBER, NAME, STRING, PUNCT };
  Kind kind = END;
  std::string text; // a name, a string's contents, a punctuation character or a number as written
  double value = 0;
  std::size_t line = 0;
};

inline std::string number_text(double v, int precision = 17)
{
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

// The whole script at once: statements may span lines, and an error anywhere (an unterminated comment) is an
// error of the file.
inline std::vector<Token> tokenize(const std::string& path, const std::string& text)
{
  std::vector<Token> tokens;
  const std::size_t n = text.size();
  std::size_t i = 0, line = 1;
  auto digit = [&](std::size_t k) { return k < n && text[k] >= '0' && text[k] <= '9'; };
  auto letter = [&](std::size_t k) {
    return k < n && ((text[k] >= 'a' && text[k] <= 'z') || (text[k] >= 'A' && text[k] <= 'Z') || text[k] == '_');
  };
  if(text.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3; // a UTF-8 byte order mark
  while(i < n) {
    const char c = text[i];
    if(c == '\n') {
      ++line;
      ++i;
      continue;
    }
    if(c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++i;
      continue;
    }
    if(c == '/' && i + 1 < n && text[i + 1] == '/') {
      while(i < n && text[i] != '\n') ++i;
      continue;
    }
    if(c == '/' && i + 1 < n && text[i + 1] == '*') {
      const std::size_t start = line;
      i += 2;
      while(i < n && !(text[i] == '*' && i + 1 < n && text[i + 1] == '/')) {
        if(text[i] == '\n') ++line;
        ++i;
      }
      if(i >= n) throw Geo_read_error(path, start, "unterminated /* comment");
      i += 2;
      continue;
    }
    Token t;
    t.line = line;
    if(digit(i) || (c == '.' && digit(i + 1))) {
      std::size_t j = i;
      while(digit(j)) ++j;
      if(j < n && text[j] == '.') {
        ++j;
        while(digit(j)) ++j;
      }
      if(j < n && (text[j] == 'e' || text[j] == 'E' || text[j] == 'd' || text[j] == 'D')) {
        std::size_t k = j + 1;
        if(k < n && (text[k] == '+' || text[k] == '-')) ++k;
        if(digit(k)) {
          j = k;
          while(digit(j)) ++j;
        }
      }
      t.kind = Token::NUMBER;
      t.text = text.substr(i, j - i);
      std::string s = t.text;
      for(char& ch : s)
        if(ch == 'd' || ch == 'D') ch = 'e'; // Gmsh, like Fortran, also writes exponents with d
      t.value = std::strtod(s.c_str(), nullptr);
      if(!std::isfinite(t.value)) throw Geo_read_error(path, line, "number " + t.text + " is out of range");
      i = j;
    } else if(letter(i)) {
      std::size_t j = i;
      while(letter(j) || digit(j)) ++j;
      t.kind = Token::NAME;
      t.text = text.substr(i, j - i);
      i = j;
    } else if(c == '"') {
      // skipped statements (Printf, Physical names, Include) may hold strings, whose `;` must not end them
      const std::size_t start = line;
      std::size_t j = i + 1;
      while(j < n && text[j] != '"') {
        if(text[j] == '\\' && j + 1 < n) ++j;
        if(text[j] == '\n') ++line;
        ++j;
      }
      if(j >= n) throw Geo_read_error(path, start, "unterminated string");
      t.kind = Token::STRING;
      t.text = text.substr(i + 1, j - i - 1);
      i = j + 1;
    } else if(c > ' ' && c < 127) {
      t.kind = Token::PUNCT;
      t.text = std::string(1, c);
      ++i;
    } else {
      throw Geo_read_error(path, line,
                           "unexpected byte " + std::to_string(static_cast<unsigned char>(c)) + " outside a comment");
    }
    tokens.push_back(t);
  }
  Token end;
  end.line = line;
  tokens.push_back(end);
  return tokens;
}

struct Point_entity
{
  double x, y; // z is dropped: a Plane Surface of these scripts lies in z = 0
  std::size_t line;
};

struct Curve_entity
{
  std::string kind;              // as written (a piece of a split curve keeps its parent's), for messages
  bool supported;                // a kind read as a polyline; the others are kept to name them in errors
  std::vector<long long> points; // point ids in order (empty for the other kinds)
  std::size_t line;
};

struct Loop_entity
{
  std::vector<long long> curves; // signed: a negative id runs the curve backwards
  std::size_t line;
};

// Runs the script statement by statement, keeping the entities as Gmsh's built-in kernel would, up to the first
// Plane Surface, which it turns into the PSLG.
class Reader
{
public:
  Reader(const std::string& path, std::vector<Token> tokens) : path_(path), tok_(std::move(tokens)) {}

  Poly_data run()
  {
    for(;;) {
      evaluate_ = true;
      depth_ = 0;
      const Token& t = peek();
      if(t.kind == Token::END) fail(t.line, "no Plane Surface in the script");
      if(is(t, ';')) {
        next();
        continue;
      }
      if(t.kind != Token::NAME) fail(t.line, "unexpected " + describe(t) + " at the start of a statement");
      const std::string& w = t.text;
      const Token &t1 = peek(1), &t2 = peek(2);
      if(w == "Point" && is(t1, '('))
        point_statement();
      else if((w == "Line" || w == "Curve") && is(t1, "Loop"))
        loop_statement();
      else if((w == "Line" || w == "Spline" || w == "CatmullRom" || w == "BSpline") && is(t1, '('))
        curve_statement();
      else if((w == "Circle" || w == "Ellipse" || w == "Nurbs" || w == "Bezier") && is(t1, '('))
        other_curve_statement();
      else if(w == "Plane" && is(t1, "Surface") && is(t2, '('))
        return plane_surface_statement();
      else if(w == "Split")
        split_statement();
      else if(w == "Delete")
        delete_statement();
      else if(refused(w))
        fail(t.line, "'" + w + "' is outside the subset of Gmsh read here");
      else if(is(t1, '='))
        assignment();
      else {
        note_other_tag(w);
        if(is(t1, '[') || ((is(t1, '+') || is(t1, '-') || is(t1, '*') || is(t1, '/')) &&
                           (is(t2, '=') || is(t2, t1.text[0]))))
          poison(w, t.line); // a list, `+=`, `++`...: the variable's value is no longer known
        skip_statement();
      }
    }
  }

private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const
  {
    throw Geo_read_error(path_, line, problem);
  }

  // ---- tokens

  const Token& peek(std::size_t k = 0) const { return pos_ + k < tok_.size() ? tok_[pos_ + k] : tok_.back(); }
  const Token& next()
  {
    const Token& t = peek();
    if(pos_ + 1 < tok_.size()) ++pos_; // stays on END, so that no loop runs past the end
    return t;
  }
  static bool is(const Token& t, char c) { return t.kind == Token::PUNCT && t.text[0] == c; }
  static bool is(const Token& t, const char* name) { return t.kind == Token::NAME && t.text == name; }
  static std::string describe(const Token& t)
  {
    switch(t.kind) {
    case Token::END: return "end of file";
    case Token::STRING: return "a string";
    default: return "'" + t.text + "'";
    }
  }
  void expect(char c, const std::string& context)
  {
    const Token& t = peek();
    if(!is(t, c)) fail(t.line, std::string("expected '") + c + "' " + context + ", found " + describe(t));
    next();
  }

  // Skips to the `;` that ends the statement, across brackets (Field lists hold `Curve{:}`).
  void skip_statement()
  {
    const std::size_t start = peek().line;
    std::vector<char> open;
    for(;;) {
      const Token& t = peek();
      if(t.kind == Token::END) fail(start, "statement not terminated by ';'");
      next();
      if(t.kind != Token::PUNCT) continue;
      const char c = t.text[0];
      if(c == '(' || c == '[' || c == '{') {
        open.push_back(c);
      } else if(c == ')' || c == ']' || c == '}') {
        const char o = c == ')' ? '(' : c == ']' ? '[' : '{';
        if(open.empty() || open.back() != o) fail(t.line, std::string("unbalanced '") + c + "'");
        open.pop_back();
      } else if(c == ';' && open.empty()) {
        return;
      }
    }
  }

  static bool refused(const std::string& w)
  {
    static const std::set<std::string> words = {
      "For", "EndFor", "If", "ElseIf", "Else", "EndIf", "Include", "Call", "Macro", "Function", "Return", "Exit",
      "Extrude", "Translate", "Rotate", "Symmetry", "Dilate", "Affine", "Duplicata", "Recursive", "BooleanUnion",
      "BooleanIntersection", "BooleanDifference", "BooleanFragments", "SetFactory"};
    return words.count(w) != 0;
  }

  // ---- expressions

  // With evaluate_ false an expression is only parsed (a point's mesh size, which is not needed).
  double expression()
  {
    double v = product();
    while(is(peek(), '+') || is(peek(), '-')) {
      const bool plus = is(next(), '+');
      const double w = product();
      v = plus ? v + w : v - w;
    }
    return v;
  }
  double product()
  {
    double v = unary();
    while(is(peek(), '*') || is(peek(), '/')) {
      const bool times = is(next(), '*');
      const double w = unary();
      v = times ? v * w : v / w;
    }
    return v;
  }
  double unary()
  {
    if(++depth_ > 200) fail(peek().line, "expression nested too deeply");
    double v;
    if(is(peek(), '-')) {
      next();
      v = -unary();
    } else if(is(peek(), '+')) {
      next();
      v = unary();
    } else {
      v = primary();
      if(is(peek(), '^')) {
        next();
        v = std::pow(v, unary());
      }
    }
    --depth_;
    return v;
  }
  double primary()
  {
    const Token& t = next();
    if(t.kind == Token::NUMBER) return t.value;
    if(is(t, '(')) {
      const double v = expression();
      expect(')', "to close '('");
      return v;
    }
    if(t.kind != Token::NAME) fail(t.line, "expected a number, a variable or '(', found " + describe(t));
    if(is(peek(), '(') || is(peek(), '[') || is(peek(), '{') || is(peek(), '~'))
      fail(t.line, "'" + t.text + "' followed by '" + peek().text + "': functions and lists are not read here");
    const std::string& w = t.text;
    if(w == "newp") return double(max_point_ + 1);
    if(w == "newl" || w == "newc" || w == "newll" || w == "newcl" || w == "news" || w == "newsl" || w == "newv" ||
       w == "newreg")
      return double(newreg());
    if(w == "newf") return double(max_field_ + 1);
    if(w == "Pi") return 3.14159265358979323846;
    if(!evaluate_) return 0;
    const auto it = vars_.find(w);
    if(it == vars_.end()) fail(t.line, "unknown variable '" + w + "'");
    if(!it->second.known)
      fail(t.line, "variable '" + w + "' cannot be evaluated: it is set at line " + std::to_string(it->second.line) +
                     " in a form not read here" + (it->second.why.empty() ? "" : " (" + it->second.why + ")"));
    return it->second.value;
  }

  // Gmsh's default (Geometry.OldNewReg = 1) gives newl, newll, news and the pieces of Split Curve the tag after the
  // largest of all curves, loops, surfaces, volumes and physical groups. mediterranean.geo depends on it: its
  // coastline loop uses split pieces numbered after Line Loop 481.
  long long newreg() const { return (std::max)((std::max)(max_curve_, max_loop_), max_other_) + 1; }

  long long to_id(double v, std::size_t line, const std::string& what) const
  {
    if(!(std::floor(v) == v) || std::fabs(v) > 2147483647.)
      fail(line, what + " " + number_text(v) + " is not an integer tag");
    return static_cast<long long>(v);
  }
  long long tag(char open, char close, const std::string& what)
  {
    expect(open, "before the tag of the " + what);
    const std::size_t line = peek().line;
    const long long id = to_id(expression(), line, what + " tag");
    expect(close, "after the tag of the " + what);
    if(id <= 0) fail(line, what + " tag " + std::to_string(id) + " is not positive");
    return id;
  }

  // `{a, b : c, ...}` as tags; signed ones (curves of a loop) may be negative, none may be zero.
  std::vector<long long> id_list(bool signed_ids, const std::string& what)
  {
    expect('{', "to open the list of " + what + "s");
    std::vector<long long> ids;
    if(is(peek(), '}')) {
      next();
      return ids;
    }
    for(;;) {
      const std::size_t line = peek().line;
      const long long a = to_id(expression(), line, what);
      long long b = a;
      if(is(peek(), ':')) {
        next();
        b = to_id(expression(), line, what);
        if(is(peek(), ':')) fail(line, "ranges with a step are not read here");
      }
      // a budget, so that `1 : 2e9` fails instead of exhausting the memory
      stored_ids_ += std::size_t(b > a ? b - a : a - b) + 1;
      if(stored_ids_ > 50000000) fail(line, "more than 5e7 tags listed in the script");
      for(long long k = a;; k += (a <= b ? 1 : -1)) {
        if(k == 0 || (!signed_ids && k < 0)) fail(line, what + " tag " + std::to_string(k) + " is not positive");
        ids.push_back(k);
        if(k == b) break;
      }
      if(is(peek(), ',')) {
        next();
        continue;
      }
      expect('}', "to close the list of " + what + "s");
      return ids;
    }
  }

  // ---- statements

  struct Variable
  {
    bool known;
    double value;
    std::size_t line;
    std::string why;
  };

  void poison(const std::string& name, std::size_t line, const std::string& why = std::string())
  {
    vars_[name] = Variable{false, 0., line, why};
  }

  // A right-hand side that is not an expression read here (a list, a string, a function) is not an error until the
  // variable is used: scripts set many options nobody reads.
  void assignment()
  {
    const Token& name = next();
    next(); // '='
    const std::size_t start = pos_;
    try {
      const double v = expression();
      expect(';', "after the value of '" + name.text + "'");
      vars_[name.text] = Variable{true, v, name.line, std::string()};
    } catch(const Geo_read_error& e) {
      pos_ = start;
      skip_statement();
      poison(name.text, name.line, e.problem());
    }
  }

  // Tags of skipped entities that count for newreg (and newf); an unreadable tag is left out.
  void note_other_tag(const std::string& w)
  {
    std::size_t k = 1;
    long long* max = &max_other_;
    char open = '(', close = ')';
    if(w == "Physical" || w == "Ruled" || (w == "Surface" && is(peek(1), "Loop")))
      k = 2;
    else if(w == "Field") {
      max = &max_field_;
      open = '[';
      close = ']';
    } else if(w != "Surface" && w != "Volume")
      return;
    if(!is(peek(k), open)) return;
    const std::size_t start = pos_;
    pos_ += k + 1;
    try {
      const double v = expression();
      if(is(peek(), close) && std::floor(v) == v && v > 0 && v < 2147483648.)
        *max = (std::max)(*max, static_cast<long long>(v));
    } catch(const Geo_read_error&) {
    }
    pos_ = start;
  }

  void point_statement()
  {
    const std::size_t line = next().line;
    const long long id = tag('(', ')', "point");
    const std::string name = "point " + std::to_string(id);
    expect('=', "after Point(" + std::to_string(id) + ")");
    expect('{', "before the coordinates of " + name);
    double xyz[3];
    for(int k = 0; k < 3; ++k) {
      if(k > 0) expect(',', "between the coordinates x, y, z of " + name);
      xyz[k] = expression();
    }
    if(is(peek(), ',')) {
      next();
      evaluate_ = false;
      expression();
      evaluate_ = true;
    }
    expect('}', "after the coordinates of " + name);
    expect(';', "after Point(" + std::to_string(id) + ")");
    if(!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]))
      fail(line, name + " has a coordinate that is not a finite number");
    const auto old = points_.find(id);
    if(old != points_.end()) fail(line, name + " is already defined at line " + std::to_string(old->second.line));
    points_[id] = Point_entity{xyz[0], xyz[1], line};
    deleted_points_.erase(id);
    max_point_ = (std::max)(max_point_, id);
  }

  void require_new_curve(long long id, std::size_t line) const
  {
    const auto old = curves_.find(id);
    if(old != curves_.end())
      fail(line, "curve " + std::to_string(id) + " is already defined at line " + std::to_string(old->second.line));
  }

  void add_curve(long long id, const Curve_entity& c)
  {
    curves_[id] = c;
    deleted_curves_.erase(id);
    max_curve_ = (std::max)(max_curve_, id);
    for(long long p : c.points) ++uses_[p];
  }

  void curve_statement()
  {
    const Token& kw = next();
    const std::string kind = kw.text;
    const std::size_t line = kw.line;
    const long long id = tag('(', ')', "curve");
    expect('=', "after " + kind + "(" + std::to_string(id) + ")");
    const std::vector<long long> ids = id_list(false, "point");
    expect(';', "after the points of " + kind + " " + std::to_string(id));
    require_new_curve(id, line);
    if(ids.size() < 2) fail(line, kind + " " + std::to_string(id) + " needs at least 2 points");
    for(long long p : ids) {
      if(points_.count(p)) continue;
      const auto d = deleted_points_.find(p);
      fail(line, kind + " " + std::to_string(id) + " uses point " + std::to_string(p) +
                   (d != deleted_points_.end() ? ", deleted at line " + std::to_string(d->second)
                                               : ", which is not defined"));
    }
    add_curve(id, Curve_entity{kind, true, ids, line});
  }

  // Circles and the like are kept by tag only: a loop of the surface that uses one is an error, a loop that does not
  // is fine.
  void other_curve_statement()
  {
    const Token& kw = next();
    const std::string kind = kw.text;
    const std::size_t line = kw.line;
    const long long id = tag('(', ')', "curve");
    skip_statement();
    require_new_curve(id, line);
    add_curve(id, Curve_entity{kind, false, std::vector<long long>(), line});
  }

  void loop_statement()
  {
    const std::size_t line = next().line;
    next(); // Loop
    const long long id = tag('(', ')', "curve loop");
    expect('=', "after the tag of curve loop " + std::to_string(id));
    const std::vector<long long> ids = id_list(true, "curve");
    expect(';', "after the curves of curve loop " + std::to_string(id));
    const auto old = loops_.find(id);
    if(old != loops_.end())
      fail(line,
           "curve loop " + std::to_string(id) + " is already defined at line " + std::to_string(old->second.line));
    if(ids.empty()) fail(line, "curve loop " + std::to_string(id) + " is empty");
    loops_[id] = Loop_entity{ids, line};
    max_loop_ = (std::max)(max_loop_, id);
  }

  void delete_curve(long long id, std::size_t line)
  {
    const auto it = curves_.find(id);
    if(it == curves_.end()) return; // as in Gmsh: nothing to do
    for(long long p : it->second.points) --uses_[p];
    curves_.erase(it);
    deleted_curves_[id] = line;
    // Gmsh gives the largest tag back, and only that one: later new tags depend on it
    if(id == max_curve_) --max_curve_;
  }

  void delete_point(long long id, std::size_t line)
  {
    const auto it = points_.find(id);
    // Gmsh keeps a point that a curve still goes through (mediterranean.geo deletes point 7767 five times)
    if(it == points_.end() || uses_[id] > 0) return;
    points_.erase(it);
    deleted_points_[id] = line;
    if(id == max_point_) --max_point_;
  }

  // Split Curve{c} Point{p, ...}: as Gmsh's SplitCurve, the curve is cut at those of its points that are listed
  // (points not on it are ignored), the pieces become new curves numbered by newreg, and the curve is deleted. On a
  // closed curve the piece through the first point runs from the last cut round to the first one, and comes last.
  void split_statement()
  {
    const std::size_t line = next().line;
    if(!is(peek(), "Curve")) fail(line, "only 'Split Curve' is read here");
    next();
    const long long id = tag('{', '}', "curve");
    if(!is(peek(), "Point")) fail(peek().line, "expected 'Point' after Split Curve{" + std::to_string(id) + "}");
    next();
    const std::vector<long long> cuts = id_list(false, "point");
    expect(';', "after Split Curve{" + std::to_string(id) + "}");
    const auto it = curves_.find(id);
    if(it == curves_.end()) fail(line, "Split Curve: curve " + std::to_string(id) + " is not defined");
    if(!it->second.supported)
      fail(line, "Split Curve: curve " + std::to_string(id) + " is a " + it->second.kind + ", which is not read here");
    const Curve_entity parent = it->second;
    const std::vector<long long>& cp = parent.points;
    const std::set<long long> cut(cuts.begin(), cuts.end());
    const bool closed = cp.front() == cp.back();
    bool first_piece = true, wrapped = false;
    std::vector<std::vector<long long> > pieces;
    std::vector<long long> piece;
    std::size_t steps = 0;
    for(std::size_t i = 0; i < cp.size(); ++i) {
      if(++steps > 2 * cp.size() + 2) break; // cannot happen (the wrap-around stops at the first cut); a guard
      piece.push_back(cp[i]);
      if(cut.count(cp[i]) && piece.size() > 1) {
        if(wrapped) break;
        if(!(closed && first_piece)) pieces.push_back(piece);
        first_piece = false;
        piece.assign(1, cp[i]);
      }
      if(i + 1 == cp.size() && closed && !first_piece) {
        i = 0;
        wrapped = true;
      }
    }
    if(piece.size() > 1) pieces.push_back(piece);
    for(const auto& p : pieces) add_curve(newreg(), Curve_entity{parent.kind, true, p, line});
    delete_curve(id, line);
  }

  void delete_statement()
  {
    const std::size_t line = next().line;
    if(is(peek(), "Physicals") || is(peek(), "Meshes")) {
      skip_statement();
      return;
    }
    if(!is(peek(), '{')) fail(line, "only 'Delete { ... }' is read here");
    next();
    while(!is(peek(), '}')) {
      const Token& kind = next();
      const bool point = is(kind, "Point"), curve = is(kind, "Line") || is(kind, "Curve");
      if(!point && !curve && !is(kind, "Surface") && !is(kind, "Volume"))
        fail(kind.line, "expected Point, Line, Curve, Surface or Volume in Delete, found " + describe(kind));
      const std::vector<long long> ids = id_list(false, kind.text);
      expect(';', "after " + kind.text + "{...} in Delete");
      // surfaces and volumes: none is kept before the first Plane Surface
      for(long long id : ids) {
        if(point) delete_point(id, kind.line);
        if(curve) delete_curve(id, kind.line);
      }
    }
    next(); // '}'
  }

  Poly_data plane_surface_statement()
  {
    const std::size_t line = next().line;
    next(); // Surface
    const long long id = tag('(', ')', "surface");
    expect('=', "after Plane Surface(" + std::to_string(id) + ")");
    const std::vector<long long> loop_ids = id_list(true, "curve loop");
    expect(';', "after the loops of Plane Surface " + std::to_string(id));
    if(loop_ids.empty()) fail(line, "Plane Surface " + std::to_string(id) + " has no curve loop");
    return build(id, loop_ids, line);
  }

  // ---- the PSLG

  // One loop as the canonical points (0-based, identical coordinates merged) along each of its oriented curves.
  struct Loop_points
  {
    long long id;
    std::size_t line;
    std::vector<long long> curve_ids;                          // signed
    std::vector<std::vector<std::size_t> > curves;             // canonical points, consecutive repeats dropped
    std::vector<std::pair<long long, long long> > ends;        // first and last point ids, as oriented
    std::vector<std::size_t> ring;                             // the polygon, not closed
  };

  Poly_data build(long long surface, const std::vector<long long>& loop_ids, std::size_t line)
  {
    Poly_data data;
    data.origin.file = path_;
    std::map<long long, std::size_t> index_of_id;
    std::map<std::array<double, 2>, std::size_t> index_of_xy;
    auto index = [&](long long pid) {
      const auto it = index_of_id.find(pid);
      if(it != index_of_id.end()) return it->second;
      const Point_entity& p = points_.at(pid); // curves keep their points alive
      const std::array<double, 2> xy = {{p.x, p.y}};
      const auto r = index_of_xy.emplace(xy, data.points.size());
      if(r.second) data.points.push_back(xy);
      index_of_id[pid] = r.first->second;
      return r.first->second;
    };
    auto where = [](long long pid, const Point_entity& p) {
      return "point " + std::to_string(pid) + " (" + number_text(p.x) + ", " + number_text(p.y) + ")";
    };

    std::vector<Loop_points> loops;
    std::set<long long> seen;
    for(long long signed_id : loop_ids) {
      const long long lid = signed_id < 0 ? -signed_id : signed_id;
      if(!seen.insert(lid).second)
        fail(line, "Plane Surface " + std::to_string(surface) + " lists curve loop " + std::to_string(lid) + " twice");
      const auto lit = loops_.find(lid);
      if(lit == loops_.end())
        fail(line, "Plane Surface " + std::to_string(surface) + " uses curve loop " + std::to_string(lid) +
                     ", which is not defined");
      Loop_points lp;
      lp.id = lid;
      lp.line = lit->second.line;
      lp.curve_ids = lit->second.curves;
      const std::string loop_name = "curve loop " + std::to_string(lid);
      for(long long c : lp.curve_ids) {
        const long long cid = c < 0 ? -c : c;
        const auto cit = curves_.find(cid);
        if(cit == curves_.end()) {
          const auto d = deleted_curves_.find(cid);
          fail(lp.line, loop_name + " uses curve " + std::to_string(cid) +
                          (d != deleted_curves_.end() ? ", deleted at line " + std::to_string(d->second)
                                                      : ", which is not defined"));
        }
        if(!cit->second.supported)
          fail(lp.line, loop_name + " uses curve " + std::to_string(cid) + ", a " + cit->second.kind + " (line " +
                          std::to_string(cit->second.line) + "): only Line, Spline, CatmullRom and BSpline are read");
        std::vector<long long> pts = cit->second.points;
        if(c < 0) std::reverse(pts.begin(), pts.end());
        std::vector<std::size_t> seq;
        for(long long p : pts) {
          const std::size_t k = index(p);
          if(seq.empty() || seq.back() != k) seq.push_back(k);
        }
        lp.curves.push_back(seq);
        lp.ends.push_back(std::make_pair(pts.front(), pts.back()));
      }
      // Gmsh wants each curve to start where the previous one ends; points at the same position are taken as one
      const std::size_t m = lp.curves.size();
      for(std::size_t k = 0; k < m; ++k) {
        const std::size_t l = (k + 1) % m;
        if(lp.curves[k].back() != lp.curves[l].front())
          fail(lp.line, loop_name + " does not close: curve " + std::to_string(lp.curve_ids[k]) + " ends at " +
                          where(lp.ends[k].second, points_.at(lp.ends[k].second)) + " but curve " +
                          std::to_string(lp.curve_ids[l]) + " starts at " +
                          where(lp.ends[l].first, points_.at(lp.ends[l].first)));
      }
      for(const auto& seq : lp.curves)
        for(std::size_t k : seq)
          if(lp.ring.empty() || lp.ring.back() != k) lp.ring.push_back(k);
      if(lp.ring.size() > 1 && lp.ring.back() == lp.ring.front()) lp.ring.pop_back();
      loops.push_back(lp);
    }

    // one segment per consecutive pair along each curve, a curve shared by two loops giving its segments once
    std::set<std::pair<std::size_t, std::size_t> > done;
    for(const auto& lp : loops)
      for(const auto& seq : lp.curves)
        for(std::size_t k = 0; k + 1 < seq.size(); ++k) {
          const std::size_t a = (std::min)(seq[k], seq[k + 1]), b = (std::max)(seq[k], seq[k + 1]);
          if(done.insert(std::make_pair(a, b)).second) data.segments.push_back({{seq[k], seq[k + 1]}});
        }

    // The outer boundary is the loop of largest area, wherever the surface lists it (Gmsh takes the first; ocean.geo
    // lists it last). Every other loop gets a hole seed. A loop nested in a hole (an island in a lake) is just
    // one more loop: its seed removes whatever region holds the seed, see seed_candidates().
    std::vector<double> area(loops.size());
    std::size_t outer = 0;
    for(std::size_t i = 0; i < loops.size(); ++i) {
      const auto& r = loops[i].ring;
      double a = 0;
      for(std::size_t k = 0; k < r.size(); ++k) {
        const auto &p = data.points[r[k]], &q = data.points[r[(k + 1) % r.size()]];
        a += p[0] * q[1] - p[1] * q[0];
      }
      area[i] = std::fabs(a / 2);
      if(r.size() < 3 || !(area[i] > 0))
        fail(loops[i].line, "curve loop " + std::to_string(loops[i].id) + " encloses no area");
      if(area[i] > area[outer]) outer = i;
    }
    std::vector<std::size_t> holes;
    std::vector<std::vector<K::Point_2> > candidates;
    for(std::size_t i = 0; i < loops.size(); ++i)
      if(i != outer) {
        holes.push_back(i);
        candidates.push_back(seed_candidates(loops[i].ring, data));
      }
    // Each hole takes its best candidate on no segment of the PSLG (another loop may pass there). The candidates are
    // checked against all segments at once, round after round, so that many loops do not make this quadratic.
    typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
    std::vector<Box> segment_boxes;
    for(std::size_t i = 0; i < data.segments.size(); ++i) {
      const auto& g = data.segments[i];
      segment_boxes.push_back(Box(point(data, g[0]).bbox() + point(data, g[1]).bbox(), i));
    }
    std::vector<std::size_t> pick(holes.size(), 0), pending;
    for(std::size_t h = 0; h < holes.size(); ++h) pending.push_back(h);
    while(!pending.empty()) {
      std::vector<Box> seed_boxes;
      for(std::size_t h : pending) {
        const Loop_points& lp = loops[holes[h]];
        if(pick[h] == candidates[h].size())
          fail(lp.line, "found no point strictly inside curve loop " + std::to_string(lp.id) +
                          " and off every segment, for its hole seed");
        seed_boxes.push_back(Box(candidates[h][pick[h]].bbox(), h));
      }
      std::set<std::size_t> on_segment;
      CGAL::box_intersection_d(seed_boxes.begin(), seed_boxes.end(), segment_boxes.begin(), segment_boxes.end(),
                               [&](const Box& sb, const Box& gb) {
        const K::Point_2& c = candidates[sb.info()][pick[sb.info()]];
        const K::Point_2 a = point(data, data.segments[gb.info()][0]), b = point(data, data.segments[gb.info()][1]);
        if(CGAL::orientation(a, b, c) == CGAL::COLLINEAR && CGAL::collinear_are_ordered_along_line(a, c, b))
          on_segment.insert(sb.info());
      });
      pending.assign(on_segment.begin(), on_segment.end());
      for(std::size_t h : pending) ++pick[h];
    }
    for(std::size_t h = 0; h < holes.size(); ++h)
      data.holes.push_back({{candidates[h][pick[h]].x(), candidates[h][pick[h]].y()}});
    return data;
  }

  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

  static K::Point_2 point(const Poly_data& d, std::size_t i) { return K::Point_2(d.points[i][0], d.points[i][1]); }

  // Points strictly inside the loop's polygon, best first: the centroids of the largest triangles inside the loop in
  // a constrained triangulation of the loop alone (the faces not reached from the infinite one without crossing the
  // loop), kept if exact predicates find them inside, since a centroid of a sliver may be rounded off it. A seed may
  // fall inside a loop nested in this one, which then loses its region instead of this loop; the four scripts have
  // no such nesting.
  static std::vector<K::Point_2> seed_candidates(const std::vector<std::size_t>& ring, const Poly_data& d)
  {
    typedef CGAL::Triangulation_vertex_base_2<K> Vb;
    typedef CGAL::Constrained_triangulation_face_base_2<K> Fb;
    typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
    // a control polygon may cross itself: this tag splits crossing constraints instead of refusing them
    typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> Cdt;
    std::vector<K::Point_2> polygon;
    for(std::size_t k : ring) polygon.push_back(point(d, k));
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> v;
    for(const auto& p : polygon) v.push_back(cdt.insert(p));
    for(std::size_t k = 0; k < v.size(); ++k)
      if(v[k] != v[(k + 1) % v.size()]) cdt.insert_constraint(v[k], v[(k + 1) % v.size()]);
    std::vector<K::Point_2> result;
    if(cdt.dimension() < 2) return result;
    std::set<Cdt::Face_handle> outside;
    std::vector<Cdt::Face_handle> stack;
    for(Cdt::Face_handle f : cdt.all_face_handles())
      if(cdt.is_infinite(f)) {
        outside.insert(f);
        stack.push_back(f);
      }
    while(!stack.empty()) {
      const Cdt::Face_handle f = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i)
        if(!cdt.is_constrained(std::make_pair(f, i)) && outside.insert(f->neighbor(i)).second)
          stack.push_back(f->neighbor(i));
    }
    std::vector<std::pair<double, K::Point_2> > candidates;
    for(Cdt::Face_handle f : cdt.finite_face_handles())
      if(!outside.count(f)) {
        const K::Triangle_2 t = cdt.triangle(f);
        candidates.push_back(std::make_pair(std::fabs(t.area()), CGAL::centroid(t)));
      }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const std::pair<double, K::Point_2>& a, const std::pair<double, K::Point_2>& b) {
                       return a.first > b.first;
                     });
    for(const auto& c : candidates)
      if(result.size() < 100 && CGAL::bounded_side_2(polygon.begin(), polygon.end(), c.second, K()) ==
                                  CGAL::ON_BOUNDED_SIDE)
        result.push_back(c.second);
    return result;
  }

  std::string path_;
  std::vector<Token> tok_;
  std::size_t pos_ = 0;
  bool evaluate_ = true;
  int depth_ = 0;
  std::size_t stored_ids_ = 0;
  std::map<std::string, Variable> vars_;
  std::map<long long, Point_entity> points_;
  std::map<long long, Curve_entity> curves_;
  std::map<long long, Loop_entity> loops_;
  std::map<long long, std::size_t> deleted_points_, deleted_curves_; // tag -> line of the Delete
  std::map<long long, std::size_t> uses_;                              // point tag -> curves through it
  long long max_point_ = 0, max_curve_ = 0, max_loop_ = 0, max_other_ = 0, max_field_ = 0;
};

} // namespace internal

// Reads the first Plane Surface of the script as a PSLG: its loops' curves as polylines through their listed points,
// the loop of largest area as the outer boundary, one hole seed strictly inside each other loop.
//
// Points are numbered from 0 in the order the loops reach them; points at the same (x, y) are one point, and z is
// dropped. Segments join consecutive points along each curve, once each. `origin.file` is `path`; the rest of
// `origin` is left empty, so that `insert_poly()` names segments by index.
//
// Throws Geo_read_error (a std::runtime_error), `path:line: problem`, on anything outside the subset or
// inconsistent.
inline CGAL::Advancing_front_mesh_2::IO::Poly_data read_plane_surface(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw Geo_read_error(path, 0, "cannot open the file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if(in.bad()) throw Geo_read_error(path, 0, "cannot read the file");
  internal::Reader reader(path, internal::tokenize(path, text));
  return reader.run();
}

} // namespace afm_gmsh_geo

#endif // AFM_GMSH_GEO_H
