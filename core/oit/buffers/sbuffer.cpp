// S-buffer (Vasilakis & Fudos 2012): count each pixel's fragments, prefix-sum the counts into
// variable contiguous regions, store, then sort and composite each region. Memory is sized
// exactly from the count. When the total exceeds the largest storage block the device allows,
// the store and resolve run in bands of rows, each within one block (the count and the scan
// still run once): robust at any depth complexity, like the A-buffer's tiles. Only a single row
// holding more fragments than a block could lose fragments, and those are counted as dropped.
#include "oit/technique.hpp"
#include "oit/buffers/buffer_support.hpp"
#include "oit/buffers/prefix_sum.hpp"

#include "common/bindings.h"
#include "gl/shader_program.hpp"
#include "oit/color_model.hpp"
#include "oit/draw_transparent.hpp"

#include <algorithm>
#include <vector>

namespace strata {
namespace {

using namespace buffers;

struct SBufferSettings {
    double maxBlockMiB = 0;
    static const SettingsSchema<SBufferSettings>& schema() {
        static const SettingsSchema<SBufferSettings> s{
            realSetting(&SBufferSettings::maxBlockMiB, "max_block_mib", 0, 1e6, SettingChange::Reallocate,
                        "largest entry buffer in MiB (0: the device's GL_MAX_SHADER_STORAGE_BLOCK_SIZE)"),
        };
        return s;
    }
};

class SBuffer final : public TechniqueWithSettings<SBufferSettings> {
public:
    using TechniqueWithSettings::TechniqueWithSettings;

    void render(const FrameContext& frame) override {
        const ColorModel model = colorModelFor(frame.scene);
        programs_.use(model);
        if (!programs_->store.program) {
            programs_->store = buildSceneProgram("oit/buffers/sbuffer_store.frag.glsl", withColorModel({}, model));
            programs_->resolve = gl::buildProgram({"common/fullscreen.vert.glsl", "oit/buffers/resolve_array.frag.glsl"},
                                                  withColorModel({{"LAYOUT_SBUFFER", ""}}, model));
        }
        const auto pixels = std::uint64_t(frame.size.x) * frame.size.y;
        if (offsetsSize_ != pixels) {
            gl::allocateBuffer(offsets_, pixels * 4, GL_DYNAMIC_COPY, "sbuffer offsets");
            offsetsSize_ = pixels;
        }
        stats_ = {};
        const GLuint program = programs_->store.id();
        glProgramUniform1ui(program, glGetUniformLocation(program, "uWidth"), GLuint(frame.size.x));
        const GLint passLocation = glGetUniformLocation(program, "uPass");
        {
            gl::ScopedPass pass(frame.timer, "sbuffer count");
            GLuint zero = 0;
            glClearNamedBufferData(offsets_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
            counters_.reset();
            counters_.bind();
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_PIXEL_OFFSETS, offsets_.id());
            glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            setTransparentDepthState(frame);
            glProgramUniform1i(program, passLocation, 0);
            stats_.objectDraws += drawTransparent(frame, programs_->store, frame.transparentOrder);
            storeBarrier();
            ++stats_.passes;
        }
        std::uint64_t total = 0;
        {
            gl::ScopedPass pass(frame.timer, "sbuffer prefix sum");
            total = scan_.scan(offsets_.id(), pixels);
        }
        // Exactly the counted fragments when they fit in one block, else bands of rows that do.
        const std::uint64_t limit = maxEntries();
        const std::vector<Band> bands =
            total <= limit ? std::vector<Band>{{0, frame.size.y, 0}} : splitRows(frame, limit, total);
        std::uint64_t capacity = 0;
        for (std::size_t b = 0; b < bands.size(); ++b) {
            std::uint64_t end = b + 1 < bands.size() ? bands[b + 1].base : total;
            capacity = std::max(capacity, std::min(end - bands[b].base, limit));
        }
        if (entriesSize_ != capacity || !entries_) {
            gl::allocateBuffer(entries_, std::max<std::uint64_t>(capacity, 1) * kEntryBytes, GL_DYNAMIC_COPY,
                               "sbuffer entries");
            entriesSize_ = capacity;
        }
        const GLuint resolve = programs_->resolve.id();
        for (const Band& band : bands) {
            const bool whole = bands.size() == 1;
            if (!whole) {
                glEnable(GL_SCISSOR_TEST);
                glScissor(0, band.y0, frame.size.x, band.y1 - band.y0);
            }
            {
                gl::ScopedPass pass(frame.timer, "sbuffer store");
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_PIXEL_OFFSETS, offsets_.id());
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::BIND_ENTRIES, entries_.id());
                counters_.bind();
                glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
                glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
                setTransparentDepthState(frame);
                glProgramUniform1ui(program, glGetUniformLocation(program, "uCapacity"), GLuint(capacity));
                glProgramUniform1ui(program, glGetUniformLocation(program, "uBase"), GLuint(band.base));
                glProgramUniform1i(program, passLocation, 1);
                stats_.objectDraws += drawTransparent(frame, programs_->store, frame.transparentOrder);
                glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
                storeBarrier();
                ++stats_.passes;
            }
            {
                gl::ScopedPass pass(frame.timer, "sbuffer resolve");
                glBindFramebuffer(GL_FRAMEBUFFER, frame.targets.outputFramebuffer());
                glBindTextureUnit(gpu::BIND_OPAQUE_COLOR, frame.targets.opaqueColor());
                tailTargets_.bindForResolve(frame, false);
                glProgramUniform1ui(resolve, glGetUniformLocation(resolve, "uWidth"), GLuint(frame.size.x));
                glProgramUniform1ui(resolve, glGetUniformLocation(resolve, "uBase"), GLuint(band.base));
                glProgramUniform1ui(resolve, glGetUniformLocation(resolve, "uCapacity"), GLuint(capacity));
                glProgramUniform1i(resolve, glGetUniformLocation(resolve, "uTail"), 0);
                setDepthOrderUniforms(frame, resolve);
                // The band's pixels where transparent objects can lie: the output holds the opaque
                // colour elsewhere (the next band's store sets its own scissor).
                TransparentAreaScissor scissor(frame, PixelRect{{0, band.y0}, {frame.size.x, band.y1 - band.y0}});
                drawFullscreen(frame, resolve);
                ++stats_.passes;
            }
        }
        glDisable(GL_SCISSOR_TEST);
        stats_.tiles = int(bands.size());
        const std::uint64_t dropped = counters_.read()[0];
        stats_.fragmentsCaptured = total - dropped;
        stats_.fragmentsDropped = dropped;
        stats_.overflowed = dropped > 0;
        stats_.bytes = pixels * 4 + std::max<std::uint64_t>(capacity, 1) * kEntryBytes + scan_.bytes() + kCounterBytes;
    }

private:
    // Rows [y0, y1) whose entries start at `base` in the whole frame's prefix sum.
    struct Band {
        int y0, y1;
        std::uint64_t base;
    };

    std::uint64_t maxEntries() const { return gl::storageBlockElements(kEntryBytes, settings_.maxBlockMiB); }

    // Greedy bands of whole rows, each holding at most `limit` entries, from the scanned offsets
    // (read back only in this rare case: one uint per pixel).
    std::vector<Band> splitRows(const FrameContext& frame, std::uint64_t limit, std::uint64_t total) {
        const int w = frame.size.x, h = frame.size.y;
        std::vector<GLuint> offsets(std::size_t(w) * std::size_t(h));
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glGetNamedBufferSubData(offsets_.id(), 0, GLsizeiptr(offsets.size() * sizeof(GLuint)), offsets.data());
        // Row y's first entry; past the last row, the total.
        auto start = [&](int y) { return y < h ? std::uint64_t(offsets[std::size_t(y) * std::size_t(w)]) : total; };
        std::vector<Band> bands;
        for (int y0 = 0; y0 < h;) {
            int y1 = y0 + 1;  // at least one row, even one that alone exceeds the block
            while (y1 < h && start(y1 + 1) - start(y0) <= limit) ++y1;
            bands.push_back({y0, y1, start(y0)});
            y0 = y1;
        }
        return bands;
    }

    struct Programs {
        SceneProgram store;
        gl::Program resolve;
    };
    ProgramsPerColorModel<Programs> programs_;  // oit/color_model.hpp
    gl::Buffer offsets_, entries_;
    std::uint64_t offsetsSize_ = 0, entriesSize_ = 0;
    PrefixSum scan_;
    Counters counters_;
    TailTargets tailTargets_;
};

}  // namespace

TechniqueEntry sbufferEntry() {
    TechniqueInfo info{"sbuffer", "buffer", true, true, "1 count + 2 per band (store, resolve) + prefix-sum dispatches",
                       "w*h*4 offsets + 20 B per fragment (sized exactly from the count; past the largest block, the "
                       "largest band of rows) + prefix-sum block totals + 16",
                       "S-buffer: counting pass, GPU prefix sum over pixels (work-efficient block scan), variable "
                       "contiguous region per pixel, store, resolve sorting by (depth, object, primitive)"};
    info.rgbTransmittance = true;
    return techniqueEntry<SBuffer>(info);
}

}  // namespace strata
