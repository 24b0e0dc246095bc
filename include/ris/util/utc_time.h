// UTC date-times as radar products write them ("2022-01-04T17:05:58.268589",
// "2012-07-15 14:36:47"), held as whole days since 1970-01-01 plus seconds of
// the day so that microseconds survive subtraction. Leap seconds are not
// counted (a product's times span minutes; ISCE3's DateTime does the same).
//
// Example:
//   ris::UtcTime epoch = ris::parse_utc("2012-07-15 14:36:47");
//   double t_s = ris::parse_utc("2012-07-17T14:36:47").seconds_since(epoch);  // 172800
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ris {

struct UtcTime {
  std::int64_t days = 0;  // since 1970-01-01
  double seconds_of_day = 0.0;

  double seconds_since(const UtcTime& epoch) const {
    return static_cast<double>(days - epoch.days) * 86400.0 +
           (seconds_of_day - epoch.seconds_of_day);
  }
  // "YYYY-MM-DDTHH:MM:SS.ffffff"
  std::string iso() const;
};

// Parses "YYYY-MM-DD[T ]HH:MM:SS[.fff...]" (an optional trailing "Z");
// nullopt when the text is not of that form.
std::optional<UtcTime> parse_utc(std::string_view text);

// The date-time after "seconds since " in a CF-style units string
// ("seconds since 2012-07-15 14:36:47"); nullopt when absent or malformed.
std::optional<UtcTime> parse_seconds_since(std::string_view units);

}  // namespace ris
