<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1">
<context>
    <name>GeomaticsAlgorithm</name>
    <message>
        <location filename="../algorithms/base.py" line="38" />
        <source>LiDAR ground filtering</source>
        <translation>فلترة نقاط الأرض في بيانات الليدار</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="40" />
        <source>Terrain models</source>
        <translation>نماذج التضاريس</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="41" />
        <source>Image rectification</source>
        <translation>التصحيح الهندسي للصور</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="43" />
        <source>Photogrammetry</source>
        <translation>المساحة التصويرية</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="44" />
        <source>Accuracy assessment</source>
        <translation>تقييم الدقة</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="125" />
        <source>Cancelled by the user; no output was written.</source>
        <translation>ألغى المستخدم العملية؛ لم تُكتب أي مخرجات.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="130" />
        <source>Out of memory. Use a coarser cell size, a smaller extent or fewer points; no output was written.</source>
        <translation>نفدت الذاكرة. استخدم حجم خلية أكبر أو نطاقاً أصغر أو نقاطاً أقل؛ لم تُكتب أي مخرجات.</translation>
    </message>
</context>
<context>
    <name>GeomaticsProvider</name>
    <message>
        <location filename="../provider/provider.py" line="20" />
        <source>Geomatics Toolbox</source>
        <translation>صندوق أدوات الجيوماتكس</translation>
    </message>
</context>
<context>
    <name>GsdBatchAlgorithm</name>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="324" />
        <source>GSD and photogrammetric accuracy calculator (batch table)</source>
        <translation>حاسبة GSD والدقة التصويرية (جدول دفعي)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="327" />
        <source>&lt;p&gt;Runs the GSD / accuracy calculator for every row of a table (CSV, spreadsheet or any layer) and writes a table with the inputs and all results.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Input columns&lt;/b&gt; (case-insensitive): &lt;i&gt;camera&lt;/i&gt; (optional preset key: nikon_p100, dji_p4rtk, dji_p1_35, phaseone_ixm100_80), &lt;i&gt;distance&lt;/i&gt; (m, required), &lt;i&gt;sensor_width&lt;/i&gt; (mm), &lt;i&gt;image_width&lt;/i&gt; (px), &lt;i&gt;focal_length&lt;/i&gt; (mm) — required unless a camera preset is given — and optionally sensor_height, image_height, target_gsd, k_m, k_s, pyramid_level, subsampling_step, observed_sx, observed_sy, observed_sz, observed_sxyz, observed_dense_std, forward_overlap, side_overlap, stereo_base (units as in the single calculator).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Output&lt;/b&gt;: the input columns plus gsd_cm, footprint_width_m, sigma_xyz_mm, dense_resolution_cm and every other result. A row with an invalid value stops the run with an error naming the row and column.&lt;/p&gt;</source>
        <translation>&lt;p&gt;تشغّل حاسبة GSD والدقة لكل سطر من جدول (CSV أو جدول بيانات أو أي طبقة) وتكتب جدولاً بالمدخلات وجميع النتائج.&lt;/p&gt;&lt;p&gt;&lt;b&gt;أعمدة الإدخال&lt;/b&gt; (دون تمييز حالة الأحرف): &lt;i&gt;camera&lt;/i&gt; (اختياري، مفتاح كاميرا معرّفة: nikon_p100، dji_p4rtk، dji_p1_35، phaseone_ixm100_80)، &lt;i&gt;distance&lt;/i&gt; (م، إلزامي)، &lt;i&gt;sensor_width&lt;/i&gt; (مم)، &lt;i&gt;image_width&lt;/i&gt; (بكسل)، &lt;i&gt;focal_length&lt;/i&gt; (مم) — إلزامية ما لم تُحدَّد كاميرا — واختيارياً sensor_height وimage_height وtarget_gsd وk_m وk_s وpyramid_level وsubsampling_step وobserved_sx وobserved_sy وobserved_sz وobserved_sxyz وobserved_dense_std وforward_overlap وside_overlap وstereo_base (بالوحدات نفسها كما في الحاسبة المفردة).&lt;/p&gt;&lt;p&gt;&lt;b&gt;المخرج&lt;/b&gt;: أعمدة الإدخال مضافاً إليها gsd_cm وfootprint_width_m وsigma_xyz_mm وdense_resolution_cm وسائر النتائج. السطر الذي يحوي قيمة غير صالحة يوقف التشغيل برسالة تذكر السطر والعمود.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="343" />
        <source>Table of cameras and distances</source>
        <translation>جدول الكاميرات والمسافات</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="346" />
        <source>Round GSD to 0.01 cm/px like the paper</source>
        <translation>تقريب GSD إلى 0.01 سم/بكسل كما في البحث</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="348" />
        <source>GSD results</source>
        <translation>نتائج GSD</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="357" />
        <source>The table has no 'distance' column (m); columns found: {0}.</source>
        <translation>لا يحتوي الجدول على العمود 'distance' (م)؛ الأعمدة الموجودة: {0}.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="373" />
        <source>Cancelled by the user.</source>
        <translation>ألغى المستخدم العملية.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="379" />
        <source>Row {row}: unknown camera '{cam}'; known: {known}.</source>
        <translation>السطر {row}: كاميرا غير معروفة '{cam}'؛ المعروفة: {known}.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="396" />
        <source>Row {row}, column '{col}': '{val}' is not a number.</source>
        <translation>السطر {row}، العمود '{col}': القيمة '{val}' ليست رقماً.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="402" />
        <source>Row {row}: missing {cols}; give the columns or a camera preset.</source>
        <translation>السطر {row}: القيم {cols} ناقصة؛ أضف الأعمدة أو حدّد كاميرا معرّفة مسبقاً.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="408" />
        <source>Row {row}: {err}</source>
        <translation>السطر {row}: {err}</translation>
    </message>
</context>
<context>
    <name>GsdCalculatorAlgorithm</name>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="88" />
        <source>GSD and photogrammetric accuracy calculator</source>
        <translation>حاسبة دقة المسافة الأرضية للبكسل (GSD) والدقة التصويرية</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="91" />
        <source>gsd,ground sampling distance,flying height,footprint,accuracy,photogrammetry,drone,flight planning,dense matching</source>
        <translation>gsd,المسافة الأرضية للبكسل,ارتفاع الطيران,البصمة الأرضية,الدقة,المساحة التصويرية,طائرة مسيرة,تخطيط الطيران,المطابقة الكثيفة</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="95" />
        <source>&lt;p&gt;Computes the ground sampling distance (GSD) of a camera at a given distance, the image footprint, the theoretical accuracy of phototriangulation and of a dense-matching point cloud, and compares observed accuracies with the theory (Al Khalil 2019).&lt;/p&gt;&lt;p&gt;&lt;b&gt;Formulas&lt;/b&gt;: GSD [cm/px] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;); footprint = D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;; σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD; σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;; matching step P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;; dense resolution R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Example&lt;/b&gt; (the paper's Nikon Coolpix P100): DISTANCE=5.88 SENSOR_WIDTH=6.123 IMAGE_WIDTH=3648 FOCAL_LENGTH=4.6 gives GSD 0.21455 cm/px, σ&lt;sub&gt;xyz&lt;/sub&gt; 1.287 mm (1.26 mm with ROUND_GSD), R&lt;sub&gt;theo&lt;/sub&gt; 0.858 cm, footprint 7.827 m.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Parameters&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Camera preset&lt;/b&gt; (CAMERA, default Custom): fills sensor width/height, image width/height and focal length; values you enter override the preset.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Distance&lt;/b&gt; (DISTANCE, m): camera–object distance or flying height above ground. Required, &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sensor width&lt;/b&gt; (SENSOR_WIDTH, mm), &lt;b&gt;Image width&lt;/b&gt; (IMAGE_WIDTH, px), &lt;b&gt;Focal length&lt;/b&gt; (FOCAL_LENGTH, mm, the true focal length, not the 35 mm equivalent): required with the Custom camera, &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Sensor height&lt;/b&gt; (SENSOR_HEIGHT, mm) / &lt;b&gt;Image height&lt;/b&gt; (IMAGE_HEIGHT, px): optional, for the footprint height and flight spacing.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Target GSD&lt;/b&gt; (TARGET_GSD, cm/px): optional; gives the distance or flying height that achieves it.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Round GSD like the paper&lt;/b&gt; (ROUND_GSD, default no): round the GSD to 0.01 cm/px before the derived quantities.&lt;/li&gt;&lt;li&gt;&lt;b&gt;k&lt;sub&gt;m&lt;/sub&gt;&lt;/b&gt; (K_M, px, default 0.3; 0.13 for an expert operator) and &lt;b&gt;k&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (K_S, default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Pyramid level N&lt;sub&gt;p&lt;/sub&gt;&lt;/b&gt; (PYRAMID_LEVEL, default 0.5, a fraction in (0, 1], or a percentage in (0, 100] with PYRAMID_PERCENT) and &lt;b&gt;subsampling step T&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (SUBSAMPLING_STEP, px, ≥ 1, default 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Observed σx, σy, σz, σxyz&lt;/b&gt; (mm) and &lt;b&gt;observed dense-cloud std&lt;/b&gt; (cm): optional; give the observed/theoretical ratios.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Extension&lt;/b&gt; (not in the paper): stereo base (STEREO_BASE, m) → normal-case σ&lt;sub&gt;Z&lt;/sub&gt; = (D/B)(D/c)σ&lt;sub&gt;image&lt;/sub&gt; with σ&lt;sub&gt;image&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt; pixels; forward/side overlap (%) → exposure and line spacing (image height along track, width across track).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Report&lt;/b&gt; (OUTPUT_HTML): optional HTML report.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Every result is also an output number, so the graphical modeler can chain it.&lt;/p&gt;</source>
        <translation>&lt;p&gt;تحسب المسافة الأرضية للبكسل (GSD) لكاميرا على مسافة معينة، والبصمة الأرضية للصورة، والدقة النظرية للتثليث التصويري ولسحابة النقاط الناتجة عن المطابقة الكثيفة، وتقارن الدقة المرصودة بالنظرية (الخليل 2019).&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعادلات&lt;/b&gt;: GSD [سم/بكسل] = D·S&lt;sub&gt;W&lt;/sub&gt;·100/(Im&lt;sub&gt;W&lt;/sub&gt;·F&lt;sub&gt;R&lt;/sub&gt;)؛ البصمة = D·S&lt;sub&gt;W&lt;/sub&gt;/F&lt;sub&gt;R&lt;/sub&gt;؛ σ&lt;sub&gt;meas&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD؛ σ&lt;sub&gt;xyz&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt;·GSD·k&lt;sub&gt;s&lt;/sub&gt;؛ خطوة المطابقة P = T&lt;sub&gt;s&lt;/sub&gt;/N&lt;sub&gt;p&lt;/sub&gt;؛ الدقة النظرية للسحابة R&lt;sub&gt;theo&lt;/sub&gt; = P·GSD.&lt;/p&gt;&lt;p&gt;&lt;b&gt;مثال&lt;/b&gt; (كاميرا Nikon Coolpix P100 في البحث): DISTANCE=5.88 SENSOR_WIDTH=6.123 IMAGE_WIDTH=3648 FOCAL_LENGTH=4.6 يعطي GSD = 0.21455 سم/بكسل، σ&lt;sub&gt;xyz&lt;/sub&gt; = 1.287 مم (1.26 مم مع ROUND_GSD)، R&lt;sub&gt;theo&lt;/sub&gt; = 0.858 سم، البصمة 7.827 م.&lt;/p&gt;&lt;p&gt;&lt;b&gt;المعاملات&lt;/b&gt;&lt;/p&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;كاميرا معرّفة مسبقاً&lt;/b&gt; (CAMERA، الافتراضي: مخصص): تملأ عرض الحساس وارتفاعه وأبعاد الصورة والبعد البؤري؛ القيم التي تدخلها تتقدّم على قيم الكاميرا.&lt;/li&gt;&lt;li&gt;&lt;b&gt;المسافة&lt;/b&gt; (DISTANCE، م): المسافة بين الكاميرا والجسم أو ارتفاع الطيران فوق الأرض. إلزامية، &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;عرض الحساس&lt;/b&gt; (SENSOR_WIDTH، مم)، &lt;b&gt;عرض الصورة&lt;/b&gt; (IMAGE_WIDTH، بكسل)، &lt;b&gt;البعد البؤري&lt;/b&gt; (FOCAL_LENGTH، مم، البعد الحقيقي لا المكافئ لـ35 مم): إلزامية مع الكاميرا المخصصة، &amp;gt; 0.&lt;/li&gt;&lt;li&gt;&lt;b&gt;ارتفاع الحساس&lt;/b&gt; (SENSOR_HEIGHT، مم) / &lt;b&gt;ارتفاع الصورة&lt;/b&gt; (IMAGE_HEIGHT، بكسل): اختيارية، لارتفاع البصمة والمسافات بين اللقطات.&lt;/li&gt;&lt;li&gt;&lt;b&gt;GSD المطلوب&lt;/b&gt; (TARGET_GSD، سم/بكسل): اختياري؛ يعطي المسافة أو ارتفاع الطيران المحقق له.&lt;/li&gt;&lt;li&gt;&lt;b&gt;تقريب GSD كما في البحث&lt;/b&gt; (ROUND_GSD، الافتراضي: لا): يقرّب GSD إلى 0.01 سم/بكسل قبل حساب الكميات المشتقة.&lt;/li&gt;&lt;li&gt;&lt;b&gt;k&lt;sub&gt;m&lt;/sub&gt;&lt;/b&gt; (K_M، بكسل، الافتراضي 0.3؛ 0.13 لمشغّل خبير) و&lt;b&gt;k&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (K_S، الافتراضي 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;مستوى الهرم N&lt;sub&gt;p&lt;/sub&gt;&lt;/b&gt; (PYRAMID_LEVEL، الافتراضي 0.5، كسر في (0، 1]، أو نسبة مئوية في (0، 100] مع PYRAMID_PERCENT) و&lt;b&gt;خطوة الاعتيان T&lt;sub&gt;s&lt;/sub&gt;&lt;/b&gt; (SUBSAMPLING_STEP، بكسل، ≥ 1، الافتراضي 2).&lt;/li&gt;&lt;li&gt;&lt;b&gt;σx وσy وσz وσxyz المرصودة&lt;/b&gt; (مم) و&lt;b&gt;الانحراف المعياري المرصود للسحابة الكثيفة&lt;/b&gt; (سم): اختيارية؛ تعطي نسب المرصود إلى النظري.&lt;/li&gt;&lt;li&gt;&lt;b&gt;إضافة&lt;/b&gt; (ليست في البحث): قاعدة الزوج المجسم (STEREO_BASE، م) ← σ&lt;sub&gt;Z&lt;/sub&gt; = (D/B)(D/c)σ&lt;sub&gt;image&lt;/sub&gt; للحالة النظامية مع σ&lt;sub&gt;image&lt;/sub&gt; = k&lt;sub&gt;m&lt;/sub&gt; بكسل؛ التداخل الطولي/الجانبي (%) ← المسافة بين اللقطات وبين خطوط الطيران (ارتفاع الصورة باتجاه الطيران وعرضها عمودياً عليه).&lt;/li&gt;&lt;li&gt;&lt;b&gt;التقرير&lt;/b&gt; (OUTPUT_HTML): تقرير HTML اختياري.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;كل نتيجة هي أيضاً مخرج رقمي، لذا يمكن ربطها في المصمم الرسومي للنماذج.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="138" />
        <source>Custom (enter the values below)</source>
        <translation>مخصص (أدخل القيم أدناه)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="139" />
        <source>Camera preset</source>
        <translation>كاميرا معرّفة مسبقاً</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="141" />
        <source>Camera–object distance / flying height (m)</source>
        <translation>المسافة بين الكاميرا والجسم / ارتفاع الطيران (م)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="143" />
        <source>Sensor width (mm)</source>
        <translation>عرض الحساس (مم)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="145" />
        <source>Image width (px)</source>
        <translation>عرض الصورة (بكسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="147" />
        <source>Focal length, true (mm)</source>
        <translation>البعد البؤري الحقيقي (مم)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="149" />
        <source>Sensor height (mm)</source>
        <translation>ارتفاع الحساس (مم)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="151" />
        <source>Image height (px)</source>
        <translation>ارتفاع الصورة (بكسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="153" />
        <source>Target GSD (cm/px)</source>
        <translation>GSD المطلوب (سم/بكسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="155" />
        <source>Round GSD to 0.01 cm/px like the paper</source>
        <translation>تقريب GSD إلى 0.01 سم/بكسل كما في البحث</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="157" />
        <source>Measurement factor k_m (px)</source>
        <translation>معامل القياس k_m (بكسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="159" />
        <source>Safety factor k_s</source>
        <translation>معامل الأمان k_s</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="161" />
        <source>Dense matching pyramid level N_p (fraction, or % if checked below)</source>
        <translation>مستوى هرم الصور للمطابقة الكثيفة N_p (كسر، أو نسبة مئوية إذا فُعّل الخيار أدناه)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="164" />
        <source>Pyramid level is a percentage</source>
        <translation>مستوى الهرم نسبة مئوية</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="167" />
        <source>Dense matching subsampling step T_s (px)</source>
        <translation>خطوة الاعتيان في المطابقة الكثيفة T_s (بكسل)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed σx (mm)</source>
        <translation>σx المرصود (مم)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed σy (mm)</source>
        <translation>σy المرصود (مم)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed σz (mm)</source>
        <translation>σz المرصود (مم)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed σxyz (mm)</source>
        <translation>σxyz المرصود (مم)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="170" />
        <source>Observed dense-cloud std (cm)</source>
        <translation>الانحراف المعياري المرصود للسحابة الكثيفة (سم)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="177" />
        <source>Stereo base B (m) [extension]</source>
        <translation>قاعدة الزوج المجسم B (م) [إضافة]</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="179" />
        <source>Forward overlap (%) [extension]</source>
        <translation>التداخل الطولي (%) [إضافة]</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="181" />
        <source>Side overlap (%) [extension]</source>
        <translation>التداخل الجانبي (%) [إضافة]</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="183" />
        <source>Report</source>
        <translation>التقرير</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="183" />
        <source>HTML files (*.html)</source>
        <translation>ملفات HTML (*.html)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="214" />
        <source>{name} ({unit}) is required with the Custom camera: enter it or choose a camera preset.</source>
        <translation>القيمة {name} ({unit}) مطلوبة مع الكاميرا المخصصة: أدخلها أو اختر كاميرا معرّفة مسبقاً.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="223" />
        <source>DISTANCE (m) is required.</source>
        <translation>المسافة DISTANCE (م) مطلوبة.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="258" />
        <source>GSD used</source>
        <translation>GSD المستخدم</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="259" />
        <source>GSD, unrounded</source>
        <translation>GSD دون تقريب</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="260" />
        <source>Pixel pitch</source>
        <translation>أبعاد البكسل على الحساس</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="261" />
        <source>Footprint width</source>
        <translation>عرض البصمة الأرضية</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="262" />
        <source>Footprint height</source>
        <translation>ارتفاع البصمة الأرضية</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="263" />
        <source>Image measurement precision σ_meas</source>
        <translation>دقة القياس على الصورة σ_meas</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="264" />
        <source>Theoretical phototriangulation accuracy σ_xyz</source>
        <translation>الدقة النظرية للتثليث التصويري σ_xyz</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="265" />
        <source>Dense matching step P</source>
        <translation>خطوة المطابقة الكثيفة P</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="266" />
        <source>Theoretical dense-cloud resolution R_theo</source>
        <translation>الدقة النظرية للسحابة الكثيفة R_theo</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="267" />
        <source>Distance for the target GSD</source>
        <translation>المسافة اللازمة لتحقيق GSD المطلوب</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="268" />
        <source>Observed σxyz</source>
        <translation>σxyz المرصود</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="269" />
        <source>Observed / theoretical σxyz</source>
        <translation>نسبة σxyz المرصود إلى النظري</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="270" />
        <source>Observed dense std / R_theo</source>
        <translation>نسبة الانحراف المرصود للسحابة الكثيفة إلى R_theo</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="271" />
        <source>Stereo base (extension)</source>
        <translation>قاعدة الزوج المجسم (إضافة)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="272" />
        <source>Stereo planimetric precision (extension)</source>
        <translation>الدقة المستوية للزوج المجسم (إضافة)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="273" />
        <source>Stereo depth precision σ_Z (extension)</source>
        <translation>دقة العمق للزوج المجسم σ_Z (إضافة)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="274" />
        <source>Exposure spacing (extension)</source>
        <translation>المسافة بين اللقطات (إضافة)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="275" />
        <source>Flight-line spacing (extension)</source>
        <translation>المسافة بين خطوط الطيران (إضافة)</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="279" />
        <source>Distance</source>
        <translation>المسافة</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="280" />
        <source>Sensor width</source>
        <translation>عرض الحساس</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="281" />
        <source>Image width</source>
        <translation>عرض الصورة</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="282" />
        <source>Focal length</source>
        <translation>البعد البؤري</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="283" />
        <source>quantity</source>
        <translation>الكمية</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="283" />
        <source>value</source>
        <translation>القيمة</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="283" />
        <source>unit</source>
        <translation>الوحدة</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="283" />
        <source>Formulas and defaults from Al Khalil (2019); the paper finds observed phototriangulation accuracy about 3–5 times the theoretical value. Items marked (extension) are not in the paper.</source>
        <translation>المعادلات والقيم الافتراضية من الخليل (2019)؛ وجد البحث أن دقة التثليث التصويري المرصودة تعادل نحو 3–5 أضعاف القيمة النظرية. البنود المعلَّمة بـ(إضافة) ليست من البحث.</translation>
    </message>
    <message>
        <location filename="../algorithms/gsd_calculator.py" line="294" />
        <source>GSD and photogrammetric accuracy</source>
        <translation>GSD والدقة التصويرية</translation>
    </message>
</context>
</TS>
