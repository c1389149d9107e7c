<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1">
<context>
    <name>GeomaticsAlgorithm</name>
    <message>
        <location filename="../algorithms/base.py" line="38" />
        <source>LiDAR ground filtering</source>
        <translation>فیلتر کردن نقاط زمینی لایدار</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="40" />
        <source>Terrain models</source>
        <translation>مدل‌های رقومی زمین</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="41" />
        <source>Image rectification</source>
        <translation>تصحیح هندسی تصویر</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="43" />
        <source>Photogrammetry</source>
        <translation>فتوگرامتری</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="44" />
        <source>Accuracy assessment</source>
        <translation>ارزیابی دقت</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="125" />
        <source>Cancelled by the user; no output was written.</source>
        <translation>کاربر عملیات را لغو کرد؛ هیچ خروجی‌ای نوشته نشد.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="130" />
        <source>Out of memory. Use a coarser cell size, a smaller extent or fewer points; no output was written.</source>
        <translation>حافظه کافی نیست. اندازهٔ سلول بزرگ‌تر، محدودهٔ کوچک‌تر یا نقاط کمتری به کار ببرید؛ هیچ خروجی‌ای نوشته نشد.</translation>
    </message>
</context>
<context>
    <name>GeomaticsProvider</name>
    <message>
        <location filename="../provider/provider.py" line="20" />
        <source>Geomatics Toolbox</source>
        <translation>جعبه‌ابزار ژئوماتیک</translation>
    </message>
</context>
<context>
    <name>GsdBatchAlgorithm</name>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="324" />
        <source>GSD and photogrammetric accuracy calculator (batch table)</source>
        <translation>محاسبه‌گر GSD و دقت فتوگرامتری (جدول دسته‌ای)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="327" />
        <source>&lt;p&gt;Runs the GSD / accuracy calculator for every row of a table (CSV, spreadsheet or any layer) and writes a table with the inputs and all results.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Input columns&lt;/b&gt; (case-insensitive): &lt;i&gt;camera&lt;/i&gt; (optional preset key: nikon_p100, dji_p4rtk, dji_p1_35, phaseone_ixm100_80), &lt;i&gt;distance&lt;/i&gt; (m, required), &lt;i&gt;sensor_width&lt;/i&gt; (mm), &lt;i&gt;image_width&lt;/i&gt; (px), &lt;i&gt;focal_length&lt;/i&gt; (mm) — required unless a camera preset is given — and optionally sensor_height, image_height, target_gsd, k_m, k_s, pyramid_level, subsampling_step, observed_sx, observed_sy, observed_sz, observed_sxyz, observed_dense_std, forward_overlap, side_overlap, stereo_base (units as in the single calculator).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Output&lt;/b&gt;: the input columns plus gsd_cm, footprint_width_m, sigma_xyz_mm, dense_resolution_cm and every other result. A row with an invalid value stops the run with an error naming the row and column.&lt;/p&gt;</source>
        <translation>&lt;p&gt;محاسبه‌گر GSD و دقت را برای هر ردیف یک جدول (CSV، صفحه‌گسترده یا هر لایه) اجرا می‌کند و جدولی با ورودی‌ها و همهٔ نتایج می‌نویسد.&lt;/p&gt;&lt;p&gt;&lt;b&gt;ستون‌های ورودی&lt;/b&gt; (بدون حساسیت به حروف بزرگ و کوچک): &lt;i&gt;camera&lt;/i&gt; (اختیاری، کلید دوربین: nikon_p100، dji_p4rtk، dji_p1_35، phaseone_ixm100_80)، &lt;i&gt;distance&lt;/i&gt; (متر، الزامی)، &lt;i&gt;sensor_width&lt;/i&gt; (میلی‌متر)، &lt;i&gt;image_width&lt;/i&gt; (پیکسل)، &lt;i&gt;focal_length&lt;/i&gt; (میلی‌متر) — الزامی مگر آنکه دوربین داده شود — و به‌اختیار sensor_height، image_height، target_gsd، k_m، k_s، pyramid_level، subsampling_step، observed_sx، observed_sy، observed_sz، observed_sxyz، observed_dense_std، forward_overlap، side_overlap، stereo_base (با همان واحدهای محاسبه‌گر تکی).&lt;/p&gt;&lt;p&gt;&lt;b&gt;خروجی&lt;/b&gt;: ستون‌های ورودی به‌علاوهٔ gsd_cm، footprint_width_m، sigma_xyz_mm، dense_resolution_cm و دیگر نتایج. ردیفی با مقدار نامعتبر اجرا را با پیامی که ردیف و ستون را نام می‌برد متوقف می‌کند.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="343" />
        <source>Table of cameras and distances</source>
        <translation>جدول دوربین‌ها و فاصله‌ها</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="346" />
        <source>Round GSD to 0.01 cm/px like the paper</source>
        <translation>گرد کردن GSD به ۰٫۰۱ سانتی‌متر/پیکسل مانند مقاله</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="348" />
        <source>GSD results</source>
        <translation>نتایج GSD</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="357" />
        <source>The table has no 'distance' column (m); columns found: {0}.</source>
        <translation>جدول ستون 'distance' (متر) ندارد؛ ستون‌های موجود: {0}.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="373" />
        <source>Cancelled by the user.</source>
        <translation>کاربر عملیات را لغو کرد.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="379" />
        <source>Row {row}: unknown camera '{cam}'; known: {known}.</source>
        <translation>ردیف {row}: دوربین ناشناختهٔ '{cam}'؛ دوربین‌های شناخته: {known}.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="396" />
        <source>Row {row}, column '{col}': '{val}' is not a number.</source>
        <translation>ردیف {row}، ستون '{col}': مقدار '{val}' عدد نیست.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="402" />
        <source>Row {row}: missing {cols}; give the columns or a camera preset.</source>
        <translation>ردیف {row}: مقادیر {cols} وجود ندارد؛ ستون‌ها یا یک دوربین از پیش تعریف‌شده بدهید.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="408" />
        <source>Row {row}: {err}</source>
        <translation>ردیف {row}: {err}</translation>
    </message>
</context>
<context>
    <name>GsdCalculatorAlgorithm</name>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="88" />
        <source>GSD and photogrammetric accuracy calculator</source>
        <translation>محاسبه‌گر GSD (فاصلهٔ نمونه‌برداری زمینی) و دقت فتوگرامتری</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="91" />
        <source>gsd,ground sampling distance,flying height,footprint,accuracy,photogrammetry,drone,flight planning,dense matching</source>
        <translation>gsd,فاصله نمونه‌برداری زمینی,ارتفاع پرواز,پوشش زمینی,دقت,فتوگرامتری,پهپاد,طراحی پرواز,تناظریابی متراکم</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="95" />
        <source>&lt;p&gt;Computes the ground sampling distance (GSD) of a camera at a given distance, the image footprint, the theoretical accuracy of phototriangulation and of a dense-matching point cloud, and compares observed accuracies with the theory (Al Khalil 2019).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Formulas&lt;/b&gt;: GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;); footprint = D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;; σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD; σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;; matching step P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;; dense resolution R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt; (the paper's Nikon Coolpix P100): DISTANCE=5.88 SENSOR_WIDTH=6.123 IMAGE_WIDTH=3648 FOCAL_LENGTH=4.6 gives GSD 0.21455 cm/px, σ&lt;sub&gt;xyz&lt;/sub&gt; 1.287 mm (1.26 mm with ROUND_GSD), R&lt;sub&gt;theo&lt;/sub&gt; 0.858 cm, footprint 7.827 m.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Camera preset&lt;/b&gt; (CAMERA, default Custom): fills sensor width/height, image width/height and focal length; values you enter override the preset.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Distance&lt;/b&gt; (DISTANCE, m): camera–object distance or flying height above ground. Required, &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sensor width&lt;/b&gt; (SENSOR_WIDTH, mm), &lt;b&gt;Image width&lt;/b&gt; (IMAGE_WIDTH, px), &lt;b&gt;Focal length&lt;/b&gt; (FOCAL_LENGTH, mm, the true focal length, not the 35 mm equivalent): required with the Custom camera, &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sensor height&lt;/b&gt; (SENSOR_HEIGHT, mm) / &lt;b&gt;Image height&lt;/b&gt; (IMAGE_HEIGHT, px): optional, for the footprint height and flight spacing.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Target GSD&lt;/b&gt; (TARGET_GSD, cm/px): optional; gives the distance or flying height that achieves it.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Round GSD like the paper&lt;/b&gt; (ROUND_GSD, default no): round the GSD to 0.01 cm/px before the derived quantities.&lt;/li&gt;&lt;li&gt;&lt;b&gt;k&lt;sub&gt;m&lt;/sub&gt;&lt;/b&gt; (K_M, px, default 0.3; 0.13 for an expert operator) and &lt;b&gt;k&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (K_S, default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Pyramid level N&lt;sub&gt;p&lt;/sub&gt;&lt;/b&gt; (PYRAMID_LEVEL, default 0.5, a fraction in (0, 1], or a percentage in (0, 100] with PYRAMID_PERCENT) and &lt;b&gt;subsampling step T&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (SUBSAMPLING_STEP, px, ≥ 1, default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Observed σx, σy, σz, σxyz&lt;/b&gt; (mm) and &lt;b&gt;observed dense-cloud std&lt;/b&gt; (cm): optional; give the observed/theoretical ratios.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Extension&lt;/b&gt; (not in the paper): stereo base (STEREO_BASE, m) → normal-case σ&lt;sub&gt;Z&lt;/sub&gt; = (D/B)(D/c)σ&lt;sub&gt;image&lt;/sub&gt; with σ&lt;sub&gt;image&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt; pixels; forward/side overlap (%) → exposure and line spacing (image height along track, width across track).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML): optional HTML report.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Every result is also an output number, so the graphical modeler can chain it.&lt;/p&gt;</source>
        <translation>&lt;p&gt;فاصلهٔ نمونه‌برداری زمینی (GSD) یک دوربین در فاصلهٔ معین، پوشش زمینی تصویر، دقت نظری مثلث‌بندی هوایی و ابر نقاط حاصل از تناظریابی متراکم را محاسبه می‌کند و دقت مشاهده‌شده را با مقدار نظری می‌سنجد (الخلیل ۲۰۱۹).&lt;/p&gt;&lt;p&gt;&lt;b&gt;فرمول‌ها&lt;/b&gt;: GSD [سانتی‌متر/پیکسل] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;)؛ پوشش = D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;؛ σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD؛ σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;؛ گام تناظریابی P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;؛ تفکیک نظری ابر R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt; (دوربین Nikon Coolpix P100 مقاله): DISTANCE=5.88 SENSOR_WIDTH=6.123 IMAGE_WIDTH=3648 FOCAL_LENGTH=4.6 نتیجه می‌دهد GSD = 0.21455 سانتی‌متر/پیکسل، σ&lt;sub&gt;xyz&lt;/sub&gt; = 1.287 میلی‌متر (1.26 با ROUND_GSD)، R&lt;sub&gt;theo&lt;/sub&gt; = 0.858 سانتی‌متر، پوشش 7.827 متر.&lt;/p&gt;&lt;p&gt;&lt;b&gt;پارامترها&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;دوربین از پیش تعریف‌شده&lt;/b&gt; (CAMERA، پیش‌فرض: سفارشی): عرض و ارتفاع حسگر، ابعاد تصویر و فاصلهٔ کانونی را پر می‌کند؛ مقادیری که وارد کنید بر آن مقدم‌اند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;فاصله&lt;/b&gt; (DISTANCE، متر): فاصلهٔ دوربین تا شیء یا ارتفاع پرواز از زمین. الزامی، &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;عرض حسگر&lt;/b&gt; (SENSOR_WIDTH، میلی‌متر)، &lt;b&gt;عرض تصویر&lt;/b&gt; (IMAGE_WIDTH، پیکسل)، &lt;b&gt;فاصلهٔ کانونی&lt;/b&gt; (FOCAL_LENGTH، میلی‌متر، مقدار واقعی نه معادل ۳۵ میلی‌متری): برای دوربین سفارشی الزامی، &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ارتفاع حسگر&lt;/b&gt; (SENSOR_HEIGHT، میلی‌متر) / &lt;b&gt;ارتفاع تصویر&lt;/b&gt; (IMAGE_HEIGHT، پیکسل): اختیاری، برای طول پوشش و فواصل پرواز.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GSD هدف&lt;/b&gt; (TARGET_GSD، سانتی‌متر/پیکسل): اختیاری؛ فاصله یا ارتفاع پروازی را که به آن می‌رسد می‌دهد.&lt;/li&gt;&lt;li&gt;&lt;b&gt;گرد کردن GSD مانند مقاله&lt;/b&gt; (ROUND_GSD، پیش‌فرض: خیر): GSD را پیش از محاسبهٔ کمیت‌های وابسته به ۰٫۰۱ سانتی‌متر/پیکسل گرد می‌کند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;k&lt;sub&gt;m&lt;/sub&gt;&lt;/b&gt; (K_M، پیکسل، پیش‌فرض 0.3؛ 0.13 برای اپراتور خبره) و &lt;b&gt;k&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (K_S، پیش‌فرض 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;سطح هرم N&lt;sub&gt;p&lt;/sub&gt;&lt;/b&gt; (PYRAMID_LEVEL، پیش‌فرض 0.5، کسری در (0، 1]، یا درصدی در (0، 100] با PYRAMID_PERCENT) و &lt;b&gt;گام نمونه‌برداری T&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (SUBSAMPLING_STEP، پیکسل، ≥ 1، پیش‌فرض 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;σx، σy، σz و σxyz مشاهده‌شده&lt;/b&gt; (میلی‌متر) و &lt;b&gt;انحراف معیار ابر متراکم&lt;/b&gt; (سانتی‌متر): اختیاری؛ نسبت مشاهده‌شده به نظری را می‌دهند.&lt;/li&gt;&lt;li&gt;&lt;b&gt;افزوده&lt;/b&gt; (نه در مقاله): طول باز استریو (STEREO_BASE، متر) ← σ&lt;sub&gt;Z&lt;/sub&gt; = (D/B)(D/c)σ&lt;sub&gt;image&lt;/sub&gt; در حالت نرمال با σ&lt;sub&gt;image&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt; پیکسل؛ پوشش طولی/عرضی (%) ← فاصلهٔ نوردهی‌ها و خطوط پرواز (ارتفاع تصویر در امتداد پرواز، عرض آن عمود بر پرواز).&lt;/li&gt;&lt;li&gt;&lt;b&gt;گزارش&lt;/b&gt; (OUTPUT_HTML): گزارش HTML اختیاری.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;هر نتیجه یک خروجی عددی نیز هست تا در طراح گرافیکی مدل زنجیره شود.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="138" />
        <source>Custom (enter the values below)</source>
        <translation>سفارشی (مقادیر زیر را وارد کنید)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="139" />
        <source>Camera preset</source>
        <translation>دوربین از پیش تعریف‌شده</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="141" />
        <source>Camera–object distance / flying height (m)</source>
        <translation>فاصلهٔ دوربین تا شیء / ارتفاع پرواز (متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="143" />
        <source>Sensor width (mm)</source>
        <translation>عرض حسگر (میلی‌متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="145" />
        <source>Image width (px)</source>
        <translation>عرض تصویر (پیکسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="147" />
        <source>Focal length, true (mm)</source>
        <translation>فاصلهٔ کانونی واقعی (میلی‌متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="149" />
        <source>Sensor height (mm)</source>
        <translation>ارتفاع حسگر (میلی‌متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="151" />
        <source>Image height (px)</source>
        <translation>ارتفاع تصویر (پیکسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="153" />
        <source>Target GSD (cm/px)</source>
        <translation>GSD هدف (سانتی‌متر/پیکسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="155" />
        <source>Round GSD to 0.01 cm/px like the paper</source>
        <translation>گرد کردن GSD به ۰٫۰۱ سانتی‌متر/پیکسل مانند مقاله</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="157" />
        <source>Measurement factor k_m (px)</source>
        <translation>ضریب اندازه‌گیری k_m (پیکسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="159" />
        <source>Safety factor k_s</source>
        <translation>ضریب اطمینان k_s</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="161" />
        <source>Dense matching pyramid level N_p (fraction, or % if checked below)</source>
        <translation>سطح هرم تصویر در تناظریابی متراکم N_p (کسر، یا درصد اگر گزینهٔ زیر فعال باشد)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="164" />
        <source>Pyramid level is a percentage</source>
        <translation>سطح هرم به درصد است</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="167" />
        <source>Dense matching subsampling step T_s (px)</source>
        <translation>گام نمونه‌برداری تناظریابی متراکم T_s (پیکسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed σx (mm)</source>
        <translation>σx مشاهده‌شده (میلی‌متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed σy (mm)</source>
        <translation>σy مشاهده‌شده (میلی‌متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed σz (mm)</source>
        <translation>σz مشاهده‌شده (میلی‌متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed σxyz (mm)</source>
        <translation>σxyz مشاهده‌شده (میلی‌متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed dense-cloud std (cm)</source>
        <translation>انحراف معیار مشاهده‌شدهٔ ابر نقاط متراکم (سانتی‌متر)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="177" />
        <source>Stereo base B (m) [extension]</source>
        <translation>طول باز استریو B (متر) [افزوده]</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="179" />
        <source>Forward overlap (%) [extension]</source>
        <translation>پوشش طولی (%) [افزوده]</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="181" />
        <source>Side overlap (%) [extension]</source>
        <translation>پوشش عرضی (%) [افزوده]</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="183" />
        <source>Report</source>
        <translation>گزارش</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="183" />
        <source>HTML files (*.html)</source>
        <translation>پرونده‌های HTML (*.html)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="214" />
        <source>{name} ({unit}) is required with the Custom camera: enter it or choose a camera preset.</source>
        <translation>مقدار {name} ({unit}) برای دوربین سفارشی لازم است: آن را وارد کنید یا یک دوربین از پیش تعریف‌شده برگزینید.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="223" />
        <source>DISTANCE (m) is required.</source>
        <translation>فاصلهٔ DISTANCE (متر) لازم است.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="258" />
        <source>GSD used</source>
        <translation>GSD به‌کاررفته</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="259" />
        <source>GSD, unrounded</source>
        <translation>GSD بدون گرد کردن</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="260" />
        <source>Pixel pitch</source>
        <translation>اندازهٔ پیکسل روی حسگر</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="261" />
        <source>Footprint width</source>
        <translation>عرض پوشش زمینی</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="262" />
        <source>Footprint height</source>
        <translation>طول پوشش زمینی</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="263" />
        <source>Image measurement precision σ_meas</source>
        <translation>دقت اندازه‌گیری روی تصویر σ_meas</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="264" />
        <source>Theoretical phototriangulation accuracy σ_xyz</source>
        <translation>دقت نظری مثلث‌بندی هوایی σ_xyz</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="265" />
        <source>Dense matching step P</source>
        <translation>گام تناظریابی متراکم P</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="266" />
        <source>Theoretical dense-cloud resolution R_theo</source>
        <translation>تفکیک نظری ابر نقاط متراکم R_theo</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="267" />
        <source>Distance for the target GSD</source>
        <translation>فاصلهٔ لازم برای GSD هدف</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="268" />
        <source>Observed σxyz</source>
        <translation>σxyz مشاهده‌شده</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="269" />
        <source>Observed / theoretical σxyz</source>
        <translation>نسبت σxyz مشاهده‌شده به نظری</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="270" />
        <source>Observed dense std / R_theo</source>
        <translation>نسبت انحراف معیار ابر متراکم به R_theo</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="271" />
        <source>Stereo base (extension)</source>
        <translation>طول باز استریو (افزوده)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="272" />
        <source>Stereo planimetric precision (extension)</source>
        <translation>دقت مسطحاتی استریو (افزوده)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="273" />
        <source>Stereo depth precision σ_Z (extension)</source>
        <translation>دقت عمق استریو σ_Z (افزوده)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="274" />
        <source>Exposure spacing (extension)</source>
        <translation>فاصلهٔ نوردهی‌ها (افزوده)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="275" />
        <source>Flight-line spacing (extension)</source>
        <translation>فاصلهٔ خطوط پرواز (افزوده)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="279" />
        <source>Distance</source>
        <translation>فاصله</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="280" />
        <source>Sensor width</source>
        <translation>عرض حسگر</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="281" />
        <source>Image width</source>
        <translation>عرض تصویر</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="282" />
        <source>Focal length</source>
        <translation>فاصلهٔ کانونی</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="283" />
        <source>quantity</source>
        <translation>کمیت</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="283" />
        <source>value</source>
        <translation>مقدار</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="283" />
        <source>unit</source>
        <translation>واحد</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="283" />
        <source>Formulas and defaults from Al Khalil (2019); the paper finds observed phototriangulation accuracy about 3–5 times the theoretical value. Items marked (extension) are not in the paper.</source>
        <translation>فرمول‌ها و مقادیر پیش‌فرض از الخلیل (۲۰۱۹)؛ مقاله دقت مشاهده‌شدهٔ مثلث‌بندی را حدود ۳ تا ۵ برابر مقدار نظری یافته است. موارد علامت‌خورده با (افزوده) در مقاله نیستند.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="294" />
        <source>GSD and photogrammetric accuracy</source>
        <translation>GSD و دقت فتوگرامتری</translation>
    </message>
</context>
</TS>
