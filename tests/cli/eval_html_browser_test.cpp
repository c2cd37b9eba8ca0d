// The eval report page in a real browser (issue 16): headless Chromium (Debian `chromium`) renders the
// self-contained eval.html to a screenshot that must not be blank, and its DOM must hold one table row per
// combination of the sweep. Skipped, saying so, where Chromium is not installed.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "tests/cli/cli_run.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;

bool have_chromium() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

TEST(EvalHtml, OpensInAHeadlessBrowserWithOneRowPerCombination) {
  if (!have_chromium()) GTEST_SKIP() << "skipped: chromium not installed";
  const fs::path dir = testsupport::temp_dir("eval_html_browser");
  const testsupport::Outcome e = testsupport::shadowlab(
      dir, "eval tutorial --size 160x90 --biases slope,normal --sizes 256,512 --threads 2 --out report");
  ASSERT_EQ(e.code, 0) << e.err;
  const std::string page = "file://" + (dir / "report" / "eval.html").string();
  const std::string chromium = "chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars ";
  ASSERT_EQ(std::system((chromium + "--window-size=1200,900 --screenshot='" + (dir / "shot.png").string() + "' '" +
                         page + "' >/dev/null 2>&1")
                            .c_str()),
            0);
  ASSERT_EQ(std::system((chromium + "--dump-dom '" + page + "' >'" + (dir / "dom.html").string() + "' 2>/dev/null")
                            .c_str()),
            0);

  // The screenshot shows something: many distinct colours (a blank page has one).
  auto in = OIIO::ImageInput::open((dir / "shot.png").string());
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec spec = in->spec();
  std::vector<unsigned char> px(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, px.data()));
  std::set<uint32_t> colours;
  for (size_t i = 0; i + 2 < px.size(); i += size_t(spec.nchannels))
    colours.insert(uint32_t(px[i]) << 16 | uint32_t(px[i + 1]) << 8 | px[i + 2]);
  EXPECT_GT(colours.size(), 50u);

  // The table as the browser built it: a header row and one row per combination (2 biases × 2 sizes).
  const std::string dom = testsupport::slurp(dir / "dom.html");
  size_t rows = 0;
  for (size_t at = dom.find("<tr"); at != std::string::npos; at = dom.find("<tr", at + 3)) ++rows;
  EXPECT_EQ(rows, 1u + 4u);
}

}  // namespace
