// The Host, Origin and content-type rules of ris/serve/request_guard.h, case
// by case (the server tests send the same through a real socket).
#include "ris/serve/request_guard.h"

#include <gtest/gtest.h>

namespace ris {
namespace {

RequestFacts post(const std::string& host, const std::string& origin,
                  const std::string& type = "application/json") {
  return {"POST", "/api/simulate", host, origin, "", type, ""};
}

TEST(RequestGuard, LoopbackAnswersToItsNamesOnItsPortOnly) {
  const RequestGuard g("127.0.0.1", 8765);
  for (const char* ok : {"127.0.0.1:8765", "localhost:8765", "[::1]:8765", "LocalHost:8765"}) {
    EXPECT_TRUE(g.host_allowed(ok)) << ok;
  }
  for (const char* bad : {"evil.example:8765", "127.0.0.1:8766", "127.0.0.1", "localhost",
                          "127.0.0.2:8765", "localhost.:8765", "127.0.0.1:8765x", ":8765", "",
                          "127.0.0.1:+8765", "[::1]", "evil.example:8765@127.0.0.1:8765"}) {
    EXPECT_FALSE(g.host_allowed(bad)) << bad;
  }
  // Port 80: browsers leave it out.
  EXPECT_TRUE(RequestGuard("localhost", 80).host_allowed("localhost"));
}

TEST(RequestGuard, OtherAddressesAndWildcards) {
  const RequestGuard named("radar-lab.local", 9000);
  EXPECT_TRUE(named.host_allowed("radar-lab.local:9000"));
  EXPECT_FALSE(named.host_allowed("localhost:9000"));
  const RequestGuard v6("::1", 9000);
  EXPECT_TRUE(v6.host_allowed("[::1]:9000"));
  // A wildcard listens on every address: any IP literal (which no DNS
  // rebinding can produce), never another name.
  const RequestGuard any("0.0.0.0", 9000);
  EXPECT_TRUE(any.host_allowed("192.168.1.20:9000"));
  EXPECT_TRUE(any.host_allowed("[fe80::1]:9000"));
  EXPECT_TRUE(any.host_allowed("localhost:9000"));
  EXPECT_FALSE(any.host_allowed("evil.example:9000"));
  EXPECT_FALSE(any.host_allowed("192.168.1.20:9001"));
}

TEST(RequestGuard, StateChangesComeFromTheOwnPageAsJson) {
  const RequestGuard g("127.0.0.1", 8765);
  const std::string host = "127.0.0.1:8765";
  EXPECT_EQ(g.refusal(post(host, "http://127.0.0.1:8765")).status, 0);
  EXPECT_EQ(g.refusal(post("localhost:8765", "http://localhost:8765")).status, 0);
  EXPECT_EQ(g.refusal(post(host, "")).status, 0);  // curl, scripts: no Origin
  // The origin must be the one the Host names (another loopback name or port,
  // https, null: all other origins).
  for (const char* origin :
       {"http://evil.example", "http://localhost:8765", "https://127.0.0.1:8765",
        "http://127.0.0.1:8766", "null", "http://127.0.0.1:8765.evil.example"}) {
    const RequestGuard::Refusal r = g.refusal(post(host, origin));
    EXPECT_EQ(r.status, 403) << origin;
    EXPECT_NE(r.message.find(origin), std::string::npos) << r.message;
  }
  RequestFacts referred = post(host, "");
  referred.referer = "http://evil.example/a/b?c";
  EXPECT_EQ(g.refusal(referred).status, 403);
  referred.referer = "http://127.0.0.1:8765/index.html";
  EXPECT_EQ(g.refusal(referred).status, 0);
  RequestFacts cross = post(host, "");
  cross.sec_fetch_site = "cross-site";
  EXPECT_EQ(g.refusal(cross).status, 403);
  cross.sec_fetch_site = "same-origin";
  EXPECT_EQ(g.refusal(cross).status, 0);
  // Every method that is not a read needs JSON.
  for (const char* method : {"POST", "DELETE", "PUT", "PATCH"}) {
    RequestFacts f = post(host, "http://127.0.0.1:8765", "text/plain");
    f.method = method;
    EXPECT_EQ(g.refusal(f).status, 415) << method;
  }
  RequestFacts read = post(host, "", "");
  read.method = "GET";
  EXPECT_EQ(g.refusal(read).status, 0);
}

TEST(RequestGuard, JsonContentTypeIsTheMediaTypeExactly) {
  for (const char* ok : {"application/json", "Application/JSON",
                         " application/json ; charset=utf-8", "application/json;charset=UTF-8"}) {
    EXPECT_TRUE(is_json_content_type(ok)) << ok;
  }
  for (const char* bad : {"", "text/plain", "text/plain; application/json", "application/jsonp",
                          "application/json-seq", "application/x-www-form-urlencoded",
                          "multipart/form-data", "application/ json"}) {
    EXPECT_FALSE(is_json_content_type(bad)) << bad;
  }
}

TEST(RequestGuard, OriginOfUrl) {
  EXPECT_EQ(origin_of_url("http://Evil.Example:81/a?b#c"), "http://evil.example:81");
  EXPECT_EQ(origin_of_url("http://127.0.0.1:8765"), "http://127.0.0.1:8765");
  EXPECT_EQ(origin_of_url("/relative"), "");
}

}  // namespace
}  // namespace ris
