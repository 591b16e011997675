// Printing a page to A4, shared by the checks of the paper page and of the handout.

/** Prints the page to A4 at `path`: its page count (0 when the PDF's page tree is compressed, Firefox). */
export async function printed(page, path) {
  const pdf = Buffer.from(await page.pdf({ format: "A4", path }));
  // The page count from the PDF's page tree (Chromium writes it plainly; Firefox compresses it).
  const counts = [...pdf.toString("latin1").matchAll(/\/Type\s*\/Pages[^>]*?\/Count\s+(\d+)|\/Count\s+(\d+)[^>]*?\/Type\s*\/Pages/g)].map((m) => Number(m[1] || m[2]));
  return { pages: counts.length ? Math.max(...counts) : 0, bytes: pdf.length };
}
