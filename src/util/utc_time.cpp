#include "ris/util/utc_time.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

namespace ris {
namespace {

// Days from 1970-01-01 to a proleptic Gregorian date (Howard Hinnant's
// days_from_civil, http://howardhinnant.github.io/date_algorithms.html).
std::int64_t days_from_civil(std::int64_t y, unsigned m, unsigned d) {
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

bool read_int(std::string_view s, std::size_t pos, std::size_t len, int& out) {
  if (pos + len > s.size()) return false;
  const char* b = s.data() + pos;
  const auto r = std::from_chars(b, b + len, out);
  return r.ec == std::errc() && r.ptr == b + len;
}

}  // namespace

std::optional<UtcTime> parse_utc(std::string_view s) {
  while (!s.empty() && s.back() == 'Z') s.remove_suffix(1);
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, sec = 0;
  if (s.size() < 19 || s[4] != '-' || s[7] != '-' || (s[10] != 'T' && s[10] != ' ') ||
      s[13] != ':' || s[16] != ':') {
    return std::nullopt;
  }
  if (!read_int(s, 0, 4, y) || !read_int(s, 5, 2, mo) || !read_int(s, 8, 2, d) ||
      !read_int(s, 11, 2, h) || !read_int(s, 14, 2, mi) || !read_int(s, 17, 2, sec)) {
    return std::nullopt;
  }
  if (mo < 1 || mo > 12 || d < 1 || d > 31 || h > 23 || mi > 59 || sec > 60) return std::nullopt;
  double frac = 0.0;
  if (s.size() > 19) {
    if (s[19] != '.' || s.size() == 20) return std::nullopt;
    double scale = 0.1;
    for (std::size_t i = 20; i < s.size(); ++i) {
      if (s[i] < '0' || s[i] > '9') return std::nullopt;
      frac += (s[i] - '0') * scale;
      scale *= 0.1;
    }
  }
  UtcTime t;
  t.days = days_from_civil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d));
  t.seconds_of_day = h * 3600.0 + mi * 60.0 + sec + frac;
  return t;
}

std::optional<UtcTime> parse_seconds_since(std::string_view units) {
  constexpr std::string_view kPrefix = "seconds since ";
  const auto p = units.find(kPrefix);
  if (p == std::string_view::npos) return std::nullopt;
  std::string_view rest = units.substr(p + kPrefix.size());
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\0')) rest.remove_suffix(1);
  return parse_utc(rest);
}

std::string UtcTime::iso() const {
  // civil_from_days (Hinnant).
  std::int64_t z = days + 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const auto doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  std::int64_t y = static_cast<std::int64_t>(yoe) + era * 400;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  const unsigned d = doy - (153 * mp + 2) / 5 + 1;
  const unsigned m = mp < 10 ? mp + 3 : mp - 9;
  y += m <= 2 ? 1 : 0;
  const double s = seconds_of_day;
  const int h = static_cast<int>(s / 3600.0);
  const int mi = static_cast<int>((s - h * 3600.0) / 60.0);
  const double sec = s - h * 3600.0 - mi * 60.0;
  return fmt::format("{:04d}-{:02d}-{:02d}T{:02d}:{:02d}:{:09.6f}", y, m, d, h, mi, sec);
}

}  // namespace ris
